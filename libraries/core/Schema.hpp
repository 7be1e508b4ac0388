#pragma once
// A model's declared dictionary keys (name, type, default, range, one-line doc), declared once:
//
//   static Schema schema()
//   {
//       return Schema()
//           .add(Key::real("mu", "shear modulus [Pa]").positive())
//           .add(Key::real("beta", "shift of the evaluation point").defaultValue("0"));
//   }
//
// The same schema validates a dictionary (types, ranges, required keys, unknown keys with
// "did you mean"), produces the Params a model is built from, and prints `-listTypes`.

#include "Dictionary.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sph
{

enum class ValueType
{
    Real,
    Integer,
    Bool,
    Word,
    String,
    Vector,     // numbers, as many as the case dimension (or a fixed size)
    RealList,   // numbers, any count
    WordList,
    StringList, // quoted strings (plain words accepted)
    VectorList, // list of vectors
    Dict        // a sub-dictionary, validated by whoever reads it
};

std::string toString(ValueType type);

class Key
{
public:
    static Key real(std::string name, std::string doc);
    static Key integer(std::string name, std::string doc);
    static Key boolean(std::string name, std::string doc);
    static Key word(std::string name, std::string doc);
    static Key string(std::string name, std::string doc);
    static Key vector(std::string name, std::string doc);
    static Key realList(std::string name, std::string doc);
    static Key wordList(std::string name, std::string doc);
    static Key stringList(std::string name, std::string doc);
    static Key vectorList(std::string name, std::string doc);
    static Key dict(std::string name, std::string doc);
    // The name of one of the case's bodies (a word), or a list of them: checked against the
    // bodies of ValidationContext, read with Params::bodyIndex / bodyIndices.
    static Key body(std::string name, std::string doc);
    static Key bodyList(std::string name, std::string doc);

    // Dictionary text used when the key is absent ("1.5", "(0 0)", "none"). A single number
    // as the default of a vector fills every component.
    Key& defaultValue(std::string text);
    // May be absent without a default (the model asks Params::has()).
    Key& optional();
    Key& min(double value, bool inclusive = true);
    Key& max(double value, bool inclusive = true);
    Key& positive() { return min(0.0, false); }
    Key& nonNegative() { return min(0.0, true); }
    Key& range(double low, double high, bool lowInclusive = true, bool highInclusive = true);
    Key& choices(std::vector<std::string> words);
    Key& size(int components); // fixed vector size instead of the case dimension
    // A list of names (fields, bodies) in which no name may appear twice.
    Key& distinct();
    // The dictionary selects a model of `family` by its `type` (or holds entries that each do,
    // e.g. `functions`). The `type ...` of its doc ("{ type ...; }", appended when absent) is
    // then printed as the family's registered types, looked up at print time so that models
    // from the case's own libraries appear too: "{ type cubicSpline | wendlandC2; }".
    Key& selects(std::string family);

    const std::string& name() const { return name_; }
    // The doc, with the registered types of the family it selects (those available in
    // `dimension` when it is not 0).
    std::string doc(int dimension = 0) const;
    const std::string& selectedFamily() const { return family_; }
    ValueType type() const { return type_; }
    bool required() const { return !default_ && !optional_; }
    const std::optional<std::string>& defaultText() const { return default_; }
    const std::vector<std::string>& allowedWords() const { return choices_; }
    int fixedSize() const { return size_; }
    bool namesBodies() const { return bodies_; }
    bool distinctNames() const { return distinct_; }
    // "word", "list of body names", ...: the value's kind in messages and -listTypes.
    std::string typeText() const;
    bool hasRange() const { return hasMin_ || hasMax_; }
    // "(0, inf)", "[-1, 0.5)", "" when unbounded.
    std::string rangeText() const;
    bool inRange(double value) const;

private:
    Key(std::string name, ValueType type, std::string doc);
    std::string name_;
    ValueType type_;
    std::string doc_;
    std::optional<std::string> default_;
    bool optional_ = false;
    bool hasMin_ = false;
    bool hasMax_ = false;
    bool minInclusive_ = true;
    bool maxInclusive_ = true;
    double min_ = -std::numeric_limits<double>::infinity();
    double max_ = std::numeric_limits<double>::infinity();
    std::vector<std::string> choices_;
    int size_ = 0;
    bool bodies_ = false;
    bool distinct_ = false;
    std::string family_;
};

class Params;

struct ValidationContext
{
    int dimension = 0;    // components of a Vector key; 0 = not known (accept any count)
    std::string label;    // who reads the dictionary: "neoHookean", "controlDict", ...
    std::set<std::string> ignoredKeys{"type"}; // consumed by the caller (e.g. the selector)
    std::vector<std::string> bodies; // the case's bodies, in index order; empty = not known
    // The other models of the family that accept a key (for "unknown key": a key of another
    // model usually means the wrong type or a key put in the wrong dictionary).
    std::function<std::vector<std::string>(const std::string& key)> otherModelsWith;
};

// Whether a dictionary's `type` entry selects the model (and is skipped by validation, the
// selector having read it) or is one of the schema's own keys.
enum class TypeEntry
{
    selectsModel,
    isKey
};

class Schema
{
public:
    Schema& add(Key key);
    // Adds every key of `other` (e.g. keys common to all function objects).
    Schema& include(const Schema& other);

    const std::vector<Key>& keys() const { return keys_; }
    const Key* find(std::string_view name) const;
    std::vector<std::string> names() const;
    std::vector<std::string> requiredNames() const;

    // Checks `dict` against the declared keys and returns the typed values. Throws InputError
    // for a missing required key, a value of the wrong type or out of range, or an undeclared
    // key (with "did you mean").
    Params validate(const Dictionary& dict, const ValidationContext& context) const;
    // The same for a dictionary read by `label` ("a body", "studyDict"), with vectors of
    // `dimension` components (0: any count).
    Params validate(const Dictionary& dict, const std::string& label, int dimension = 0,
                    TypeEntry type = TypeEntry::selectsModel) const;

    // Lines for -listTypes: "name  type  default  range  doc".
    std::vector<std::string> describe() const;

private:
    std::vector<Key> keys_;
};

// The validated values of one dictionary, read by a model's constructor. Looking up a key the
// schema did not declare is a programming error (std::logic_error, with "did you mean").
class Params
{
public:
    double real(std::string_view key) const;
    long integer(std::string_view key) const;
    bool boolean(std::string_view key) const;
    const std::string& word(std::string_view key) const;
    const std::string& string(std::string_view key) const;
    const std::vector<double>& vector(std::string_view key) const;
    const std::vector<double>& realList(std::string_view key) const;
    const std::vector<std::string>& wordList(std::string_view key) const;
    const std::vector<std::string>& stringList(std::string_view key) const;
    const std::vector<std::vector<double>>& vectorList(std::string_view key) const;
    const Dictionary& dict(std::string_view key) const;
    // The index of a body key's value (Key::body) in the case's bodies, and of each name of a
    // Key::bodyList, in the order written. Needs the bodies in the ValidationContext.
    std::size_t bodyIndex(std::string_view key) const;
    std::vector<std::size_t> bodyIndices(std::string_view key) const;

    // Has a value (written or defaulted). Only optional keys without default can lack one.
    bool has(std::string_view key) const;
    // Written in the dictionary (not defaulted).
    bool given(std::string_view key) const;
    // The value as written in the dictionary, or the declared default: "3.0e4", "(0.1 0)".
    const std::string& written(std::string_view key) const;
    // "key=value, key=value" for every key with a value, in declaration order, as written (or
    // defaulted): the parameters of a model's summary.
    std::string summary() const;
    // Where the value was written (the dictionary itself when defaulted).
    SourceLocation location(std::string_view key) const;
    // Where element `index` of a list value was written (the whole value when not a list).
    SourceLocation location(std::string_view key, std::size_t index) const;
    // An InputError pointing at the key's value: for checks the schema cannot express.
    [[noreturn]] void fail(std::string_view key, const std::string& message,
                           std::vector<std::string> notes = {}) const;
    // The same, pointing at element `index` of a list value.
    [[noreturn]] void fail(std::string_view key, std::size_t index, const std::string& message,
                           std::vector<std::string> notes = {}) const;

    const Dictionary& source() const { return *source_; }
    int dimension() const { return context_.dimension; }
    const std::string& label() const { return context_.label; }

private:
    friend class Schema;
    struct Value
    {
        Key key = Key::real("", "");
        bool present = false; // has a value
        bool given = false;   // written in the dictionary
        std::string written;  // the value's text, as written or defaulted
        SourceLocation where;
        std::vector<SourceLocation> elements; // of a list value
        double real = 0.0;
        long integer = 0;
        bool boolean = false;
        std::string text;
        std::vector<double> reals;
        std::vector<std::string> words;
        std::vector<std::vector<double>> vectors;
        const Dictionary* dict = nullptr;
    };
    const Value& get(std::string_view key, ValueType expected) const;

    const Dictionary* source_ = nullptr;
    ValidationContext context_;
    std::vector<Value> values_;
};

} // namespace sph
