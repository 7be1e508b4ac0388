#pragma once
// The parsed form of an OpenFOAM-style dictionary (design guide §3).
//
//   key value;            an entry whose value is a stream of items (words, numbers, strings, lists)
//   name { ... }          a sub-dictionary
//   (1 2 3)               a list item; lists nest
//
// Every entry and item remembers where it was written, so later typed look-ups (Schema/Params)
// can report errors at the exact file, line and column.

#include "SourceLocation.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sph
{

class Dictionary;

// One element of an entry's value.
class Item
{
public:
    enum class Kind
    {
        Word,
        Number,
        String,
        List
    };

    static Item word(std::string text, SourceLocation where);
    static Item number(std::string text, double value, SourceLocation where);
    static Item string(std::string text, SourceLocation where);
    static Item list(std::vector<Item> items, SourceLocation open);

    Kind kind() const { return kind_; }
    bool isList() const { return kind_ == Kind::List; }
    const std::string& text() const { return text_; }
    double number() const { return number_; }
    const std::vector<Item>& items() const { return items_; }
    const SourceLocation& location() const { return location_; }

    // "word 'abc'", "number 3.5", "string \"x\"", "list of 2 items"
    std::string describe() const;
    // Dictionary text that reads back to the same item: `abc`, `3.5`, `"x"`, `(1 2)`.
    std::string toText() const;

private:
    Kind kind_ = Kind::Word;
    std::string text_;
    double number_ = 0.0;
    std::vector<Item> items_;
    SourceLocation location_;
};

class Entry
{
public:
    Entry(std::string key, SourceLocation keyLocation, std::vector<Item> value);
    Entry(std::string key, SourceLocation keyLocation, std::unique_ptr<Dictionary> dict);
    Entry(const Entry& other);
    Entry(Entry&&) noexcept;
    Entry& operator=(const Entry& other);
    Entry& operator=(Entry&&) noexcept;
    ~Entry();

    const std::string& key() const { return key_; }
    const SourceLocation& keyLocation() const { return keyLocation_; }
    bool isDict() const { return dict_ != nullptr; }
    const Dictionary& dict() const { return *dict_; }
    Dictionary& dict() { return *dict_; }
    const std::vector<Item>& items() const { return items_; }
    // Where the value starts (first item, or the sub-dictionary's key), for error messages.
    SourceLocation valueLocation() const;

    // Entries brought in by a `$name;` merge may be overridden once by a later explicit entry.
    bool overridable() const { return overridable_; }
    void setOverridable(bool value) { overridable_ = value; }

    // Replace the value (used by `-set`); the entry becomes a stream entry.
    void setItems(std::vector<Item> items);

    // Whether a `$name` elsewhere copied this entry: then it is a shared definition (e.g. a
    // material used by two bodies) rather than an entry of its own.
    bool referenced() const { return referenced_; }
    void markReferenced() const { referenced_ = true; }

private:
    friend class Dictionary;
    std::string key_;
    SourceLocation keyLocation_;
    std::vector<Item> items_;
    std::unique_ptr<Dictionary> dict_;
    bool overridable_ = false;
    mutable bool referenced_ = false;
};

class Dictionary
{
public:
    // name: the path of keys from the file's top ("" for a file), shown in messages as
    // 'ringA/material'. location: the key that opened it (or line 0 of the file).
    Dictionary(std::string name, SourceLocation location);
    Dictionary(const Dictionary& other);
    Dictionary& operator=(const Dictionary& other);
    ~Dictionary();

    const std::string& name() const { return name_; }
    // 'ringA/material' or, for a whole file, the file's name.
    std::string displayName() const;
    const SourceLocation& location() const { return location_; }
    // The closing brace (or end of file): where a missing key would have gone.
    const SourceLocation& endLocation() const { return endLocation_; }
    void setEndLocation(SourceLocation where) { endLocation_ = std::move(where); }
    const Dictionary* parent() const { return parent_; }
    const Dictionary& topLevel() const;

    const std::vector<Entry>& entries() const { return entries_; }
    std::vector<Entry>& entries() { return entries_; }
    const Entry* find(std::string_view key) const;
    Entry* find(std::string_view key);
    std::vector<std::string> keys() const;
    bool empty() const { return entries_.empty(); }

    // Adds an entry; a duplicate key is an InputError naming both places, unless the earlier
    // entry is overridable (came from a `$name;` merge), in which case it is replaced.
    Entry& add(Entry entry);

    // `$a.b` look-up as written inside this dictionary: the first component is searched here,
    // then in the enclosing dictionaries; the rest descend into sub-dictionaries.
    const Entry* lookupScoped(std::string_view path) const;
    // Keys visible from here (for "did you mean" on an undefined variable).
    std::vector<std::string> visibleKeys() const;

    // Renames this dictionary (and its sub-dictionaries) as a sub-dictionary `name` of parent.
    void reparent(const Dictionary* parent, const std::string& name);

private:
    std::string name_;
    SourceLocation location_;
    SourceLocation endLocation_;
    const Dictionary* parent_ = nullptr;
    std::vector<Entry> entries_;
};

} // namespace sph
