#pragma once
// Schema validation's reader of one dictionary value: converts the items of an entry to the
// declared key's type, with the type, range, choice and size checks and their messages.
// Internal to sphCore (Schema::validate is its only user).

#include "Dictionary.hpp"
#include "InputError.hpp"
#include "Schema.hpp"

#include <string>
#include <vector>

namespace sph
{

// Reads one value of `key` from `items`; `owner` names the dictionary in messages.
class ValueReader
{
public:
    ValueReader(const Key& key, const ValidationContext& context, std::string owner)
        : key_(key), context_(context), owner_(std::move(owner))
    {
    }

    // Converts `items` into the output of the key's type (isDefault: they are the declared
    // default, so an error there is the model's bug); throws InputError at the offending item.
    void read(const std::vector<Item>& items, const SourceLocation& keyWhere, bool isDefault,
              double& real, long& integer, bool& boolean, std::string& text,
              std::vector<double>& reals, std::vector<std::string>& words,
              std::vector<std::vector<double>>& vectors);
    // "a vector of 2 numbers like (0 0)", "true or false", ...: what the key takes.
    std::string expected() const;
    // The error for an item of the wrong kind.
    InputError mismatch(const Item& item) const;

private:
    static std::string example(int n);
    std::vector<std::string> notes() const;
    double number(const Item& item) const;
    long wholeNumber(const Item& item) const;
    void checkRange(const Item& item, double value) const;  // checkNormal and the key's range
    void checkNormal(const Item& item, double value) const; // not subnormal (4.9e-324)
    bool truthValue(const Item& item) const;
    std::string wordValue(const Item& item) const;
    void checkBody(const Item& item) const;
    // For a Key::distinct list: `item`, the last of `words` read so far, is not a repeat.
    void checkDistinct(const Item& item, const std::vector<std::string>& words) const;
    std::string stringValue(const Item& item) const;
    const std::vector<Item>& listItems(const Item& item) const;
    std::vector<double> vectorValue(const Item& item, int components) const;

    const Key& key_;
    const ValidationContext& context_;
    std::string owner_;
    bool isDefault_ = false;
};

} // namespace sph
