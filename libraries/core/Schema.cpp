#include "Schema.hpp"

#include "DictionaryParser.hpp"
#include "InputError.hpp"
#include "Suggest.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sph
{

std::string toString(ValueType type)
{
    switch (type)
    {
    case ValueType::Real:
        return "real";
    case ValueType::Integer:
        return "integer";
    case ValueType::Bool:
        return "bool";
    case ValueType::Word:
        return "word";
    case ValueType::String:
        return "string";
    case ValueType::Vector:
        return "vector";
    case ValueType::RealList:
        return "list of reals";
    case ValueType::WordList:
        return "list of words";
    case ValueType::StringList:
        return "list of strings";
    case ValueType::VectorList:
        return "list of vectors";
    case ValueType::Dict:
        return "dictionary";
    }
    return "?";
}

// ----------------------------------------------------------------------------------------- Key

Key::Key(std::string name, ValueType type, std::string doc)
    : name_(std::move(name)), type_(type), doc_(std::move(doc))
{
}

Key Key::real(std::string name, std::string doc) { return {std::move(name), ValueType::Real, std::move(doc)}; }
Key Key::integer(std::string name, std::string doc) { return {std::move(name), ValueType::Integer, std::move(doc)}; }
Key Key::boolean(std::string name, std::string doc) { return {std::move(name), ValueType::Bool, std::move(doc)}; }
Key Key::word(std::string name, std::string doc) { return {std::move(name), ValueType::Word, std::move(doc)}; }
Key Key::string(std::string name, std::string doc) { return {std::move(name), ValueType::String, std::move(doc)}; }
Key Key::vector(std::string name, std::string doc) { return {std::move(name), ValueType::Vector, std::move(doc)}; }
Key Key::realList(std::string name, std::string doc) { return {std::move(name), ValueType::RealList, std::move(doc)}; }
Key Key::wordList(std::string name, std::string doc) { return {std::move(name), ValueType::WordList, std::move(doc)}; }
Key Key::stringList(std::string name, std::string doc) { return {std::move(name), ValueType::StringList, std::move(doc)}; }
Key Key::vectorList(std::string name, std::string doc) { return {std::move(name), ValueType::VectorList, std::move(doc)}; }
Key Key::dict(std::string name, std::string doc) { return {std::move(name), ValueType::Dict, std::move(doc)}; }

Key& Key::defaultValue(std::string text)
{
    default_ = std::move(text);
    return *this;
}

Key& Key::optional()
{
    optional_ = true;
    return *this;
}

Key& Key::min(double value, bool inclusive)
{
    hasMin_ = true;
    min_ = value;
    minInclusive_ = inclusive;
    return *this;
}

Key& Key::max(double value, bool inclusive)
{
    hasMax_ = true;
    max_ = value;
    maxInclusive_ = inclusive;
    return *this;
}

Key& Key::range(double low, double high, bool lowInclusive, bool highInclusive)
{
    return min(low, lowInclusive).max(high, highInclusive);
}

Key& Key::choices(std::vector<std::string> words)
{
    choices_ = std::move(words);
    return *this;
}

Key& Key::size(int components)
{
    size_ = components;
    return *this;
}

namespace
{

std::string formatNumber(double value)
{
    if (std::isinf(value))
    {
        return value > 0 ? "inf" : "-inf";
    }
    std::ostringstream out;
    out << value;
    return out.str();
}

} // namespace

std::string Key::rangeText() const
{
    if (!hasRange())
    {
        return {};
    }
    return std::string(hasMin_ && minInclusive_ ? "[" : "(") + formatNumber(min_) + ", " +
           formatNumber(max_) + (hasMax_ && maxInclusive_ ? "]" : ")");
}

bool Key::inRange(double value) const
{
    if (std::isnan(value))
    {
        return false;
    }
    if (hasMin_ && (minInclusive_ ? value < min_ : value <= min_))
    {
        return false;
    }
    if (hasMax_ && (maxInclusive_ ? value > max_ : value >= max_))
    {
        return false;
    }
    return true;
}

// -------------------------------------------------------------------------------------- Schema

Schema& Schema::add(Key key)
{
    if (find(key.name()))
    {
        throw std::logic_error("schema declares key '" + key.name() + "' twice");
    }
    keys_.push_back(std::move(key));
    return *this;
}

Schema& Schema::include(const Schema& other)
{
    for (const Key& key : other.keys_)
    {
        add(key);
    }
    return *this;
}

const Key* Schema::find(std::string_view name) const
{
    for (const Key& key : keys_)
    {
        if (key.name() == name)
        {
            return &key;
        }
    }
    return nullptr;
}

std::vector<std::string> Schema::names() const
{
    std::vector<std::string> result;
    for (const Key& key : keys_)
    {
        result.push_back(key.name());
    }
    return result;
}

std::vector<std::string> Schema::requiredNames() const
{
    std::vector<std::string> result;
    for (const Key& key : keys_)
    {
        if (key.required())
        {
            result.push_back(key.name());
        }
    }
    return result;
}

namespace
{

// Reads one value of `key` from `items` into `value`; `owner` names the dictionary in messages.
class ValueReader
{
public:
    ValueReader(const Key& key, const ValidationContext& context, std::string owner)
        : key_(key), context_(context), owner_(std::move(owner))
    {
    }

    void read(const std::vector<Item>& items, const SourceLocation& keyWhere, bool isDefault,
              double& real, long& integer, bool& boolean, std::string& text,
              std::vector<double>& reals, std::vector<std::string>& words,
              std::vector<std::vector<double>>& vectors)
    {
        isDefault_ = isDefault;
        if (items.empty())
        {
            throw InputError(keyWhere, "'" + key_.name() + "' has no value");
        }
        if (items.size() > 1)
        {
            throw InputError(items[1].location(),
                             "'" + key_.name() + "' takes one value (" + expected() + "), found " +
                                 std::to_string(items.size()) + " items",
                             {"Is a ';' missing after " + items[0].toText() + "?"});
        }
        const Item& item = items[0];
        switch (key_.type())
        {
        case ValueType::Real:
            real = number(item);
            break;
        case ValueType::Integer:
            integer = wholeNumber(item);
            break;
        case ValueType::Bool:
            boolean = truthValue(item);
            break;
        case ValueType::Word:
            text = wordValue(item);
            break;
        case ValueType::String:
            text = stringValue(item);
            break;
        case ValueType::Vector:
            reals = vectorValue(item, key_.fixedSize() ? key_.fixedSize() : context_.dimension);
            break;
        case ValueType::RealList:
            for (const Item& element : listItems(item))
            {
                reals.push_back(number(element));
            }
            break;
        case ValueType::WordList:
            for (const Item& element : listItems(item))
            {
                words.push_back(wordValue(element));
            }
            break;
        case ValueType::StringList:
            for (const Item& element : listItems(item))
            {
                words.push_back(stringValue(element));
            }
            break;
        case ValueType::VectorList:
            for (const Item& element : listItems(item))
            {
                vectors.push_back(vectorValue(element, key_.fixedSize() ? key_.fixedSize()
                                                                         : context_.dimension));
            }
            break;
        case ValueType::Dict:
            throw mismatch(item);
        }
    }

    std::string expected() const
    {
        switch (key_.type())
        {
        case ValueType::Vector:
        {
            const int n = key_.fixedSize() ? key_.fixedSize() : context_.dimension;
            return n > 0 ? "a vector of " + std::to_string(n) + " number" + (n == 1 ? "" : "s") +
                               " like " + example(n)
                         : "a vector like (0 0)";
        }
        case ValueType::Dict:
            return "a dictionary { ... }";
        case ValueType::Bool:
            return "true or false";
        default:
            return "a " + toString(key_.type());
        }
    }

    InputError mismatch(const Item& item) const
    {
        return InputError(item.location(),
                          "'" + key_.name() + "' in '" + owner_ + "' must be " + expected() +
                              ", found " + item.describe(),
                          notes());
    }

private:
    static std::string example(int n)
    {
        std::string text = "(";
        for (int i = 0; i < n; ++i)
        {
            text += i ? " 0" : "0";
        }
        return text + ")";
    }

    std::vector<std::string> notes() const
    {
        std::vector<std::string> result;
        if (!key_.doc().empty())
        {
            result.push_back("'" + key_.name() + "': " + key_.doc() + ".");
        }
        if (isDefault_)
        {
            result.push_back("(This is the declared default of the key: a bug in the model.)");
        }
        return result;
    }

    double number(const Item& item) const
    {
        if (item.kind() != Item::Kind::Number)
        {
            throw mismatch(item);
        }
        checkRange(item, item.number());
        return item.number();
    }

    long wholeNumber(const Item& item) const
    {
        if (item.kind() != Item::Kind::Number || std::floor(item.number()) != item.number() ||
            std::abs(item.number()) > 9.0e15)
        {
            throw InputError(item.location(),
                             "'" + key_.name() + "' in '" + owner_ +
                                 "' must be a whole number, found " + item.describe(),
                             notes());
        }
        checkRange(item, item.number());
        return static_cast<long>(item.number());
    }

    void checkRange(const Item& item, double value) const
    {
        if (!key_.inRange(value))
        {
            throw InputError(item.location(),
                             key_.name() + " = " + item.text() + " must lie in " +
                                 key_.rangeText(),
                             notes());
        }
    }

    bool truthValue(const Item& item) const
    {
        static const std::vector<std::string> yes{"true", "yes", "on"};
        static const std::vector<std::string> no{"false", "no", "off"};
        if (item.kind() == Item::Kind::Word)
        {
            for (const auto& w : yes)
            {
                if (item.text() == w)
                {
                    return true;
                }
            }
            for (const auto& w : no)
            {
                if (item.text() == w)
                {
                    return false;
                }
            }
        }
        throw InputError(item.location(),
                         "'" + key_.name() + "' in '" + owner_ + "' must be true or false, found " +
                             item.describe(),
                         {"Accepted: true/false, yes/no, on/off."});
    }

    std::string wordValue(const Item& item) const
    {
        if (item.kind() != Item::Kind::Word)
        {
            throw mismatch(item);
        }
        const auto& allowed = key_.allowedWords();
        if (!allowed.empty() &&
            std::find(allowed.begin(), allowed.end(), item.text()) == allowed.end())
        {
            std::vector<std::string> lines{"Valid values for '" + key_.name() + "': " +
                                           joinSorted(allowed)};
            const std::string hint = didYouMean(item.text(), allowed);
            if (!hint.empty())
            {
                lines.push_back(hint);
            }
            throw InputError(item.location(),
                             "unknown value '" + item.text() + "' for '" + key_.name() + "' in '" +
                                 owner_ + "'",
                             lines);
        }
        return item.text();
    }

    std::string stringValue(const Item& item) const
    {
        if (item.kind() != Item::Kind::String && item.kind() != Item::Kind::Word)
        {
            throw mismatch(item);
        }
        return item.text();
    }

    const std::vector<Item>& listItems(const Item& item) const
    {
        if (!item.isList())
        {
            throw InputError(item.location(),
                             "'" + key_.name() + "' in '" + owner_ + "' must be a list ( ... ), found " +
                                 item.describe(),
                             notes());
        }
        return item.items();
    }

    std::vector<double> vectorValue(const Item& item, int components) const
    {
        if (!item.isList())
        {
            throw mismatch(item);
        }
        if (components > 0 && static_cast<int>(item.items().size()) != components)
        {
            std::vector<std::string> lines = notes();
            if (!key_.fixedSize())
            {
                lines.insert(lines.begin(), "The case is " + std::to_string(components) +
                                                "D (system/sphSchemes 'dimension'): vectors have " +
                                                std::to_string(components) + " component" +
                                                (components == 1 ? "" : "s") + ".");
            }
            throw InputError(item.location(),
                             "'" + key_.name() + "' in '" + owner_ + "' must be " + expected() +
                                 ", found " + std::to_string(item.items().size()) + " component" +
                                 (item.items().size() == 1 ? "" : "s"),
                             lines);
        }
        std::vector<double> result;
        for (const Item& element : item.items())
        {
            if (element.kind() != Item::Kind::Number)
            {
                throw InputError(element.location(),
                                 "'" + key_.name() + "' in '" + owner_ +
                                     "': a vector component must be a number, found " +
                                     element.describe(),
                                 notes());
            }
            result.push_back(element.number());
        }
        return result;
    }

    const Key& key_;
    const ValidationContext& context_;
    std::string owner_;
    bool isDefault_ = false;
};

} // namespace

Params Schema::validate(const Dictionary& dict, const ValidationContext& context) const
{
    Params params;
    params.source_ = &dict;
    params.context_ = context;
    const std::string owner = dict.displayName();
    const std::string label = context.label.empty() ? owner : context.label;

    // Undeclared keys first: a typo of a required key then reads "unknown key 'mue' ... Did you
    // mean 'mu'?" rather than "missing key 'mu'".
    for (const Entry& entry : dict.entries())
    {
        if (context.ignoredKeys.count(entry.key()) || find(entry.key()))
        {
            continue;
        }
        std::vector<std::string> valid = names();
        for (const std::string& ignored : context.ignoredKeys)
        {
            valid.push_back(ignored);
        }
        std::vector<std::string> notes{label + " accepts: " + joinSorted(valid)};
        const std::string hint = didYouMean(entry.key(), valid);
        if (!hint.empty())
        {
            notes.push_back(hint);
        }
        throw InputError(entry.keyLocation(),
                         "unknown key '" + entry.key() + "' in '" + owner + "'", notes);
    }

    for (const Key& key : keys_)
    {
        Params::Value value;
        value.key = key;
        const Entry* entry = dict.find(key.name());
        ValueReader reader(key, context, owner);
        if (entry)
        {
            value.present = true;
            value.given = true;
            value.where = entry->valueLocation();
            if (key.type() == ValueType::Dict)
            {
                if (!entry->isDict())
                {
                    throw reader.mismatch(entry->items().front());
                }
                value.dict = &entry->dict();
            }
            else if (entry->isDict())
            {
                throw InputError(entry->keyLocation(),
                                 "'" + key.name() + "' in '" + owner + "' must be " +
                                     reader.expected() + ", found a dictionary { ... }",
                                 {"'" + key.name() + "': " + key.doc() + "."});
            }
            else
            {
                reader.read(entry->items(), entry->keyLocation(), false, value.real,
                            value.integer, value.boolean, value.text, value.reals, value.words,
                            value.vectors);
                if (entry->items().size() == 1 && entry->items()[0].isList())
                {
                    for (const Item& element : entry->items()[0].items())
                    {
                        value.elements.push_back(element.location());
                    }
                }
            }
        }
        else if (key.defaultText())
        {
            value.present = true;
            value.where = dict.location();
            auto source = std::make_shared<const SourceText>(
                "<default of '" + key.name() + "'>", *key.defaultText());
            std::vector<Item> items = DictionaryParser::parseValue(source, *key.defaultText(), 1);
            // A single number as the default of a vector fills every component.
            if (key.type() == ValueType::Vector && items.size() == 1 &&
                items[0].kind() == Item::Kind::Number)
            {
                const int n = key.fixedSize() ? key.fixedSize() : std::max(1, context.dimension);
                value.reals.assign(static_cast<std::size_t>(n), items[0].number());
            }
            else
            {
                reader.read(items, dict.location(), true, value.real, value.integer,
                            value.boolean, value.text, value.reals, value.words, value.vectors);
            }
        }
        else if (key.required())
        {
            const std::vector<std::string> needed = requiredNames();
            SourceLocation where = dict.location();
            throw InputError(where,
                             "missing required key '" + key.name() + "' in '" + owner + "'",
                             {"(" + label + " needs: " + joinSorted(needed) + ")",
                              "'" + key.name() + "': " + key.doc() + " (" + reader.expected() +
                                  (key.hasRange() ? ", in " + key.rangeText() : "") + ")."});
        }
        params.values_.push_back(std::move(value));
    }
    return params;
}

std::vector<std::string> Schema::describe() const
{
    std::vector<std::string> lines;
    for (const Key& key : keys_)
    {
        std::string line = key.name() + "  (" + toString(key.type());
        if (key.required())
        {
            line += ", required";
        }
        else if (key.defaultText())
        {
            line += ", default " + *key.defaultText();
        }
        else
        {
            line += ", optional";
        }
        if (key.hasRange())
        {
            line += ", range " + key.rangeText();
        }
        if (!key.allowedWords().empty())
        {
            line += ", one of: " + joinSorted(key.allowedWords(), " ");
        }
        line += ")  " + key.doc();
        lines.push_back(line);
    }
    return lines;
}

// -------------------------------------------------------------------------------------- Params

const Params::Value& Params::get(std::string_view key, ValueType expected) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            if (value.key.type() != expected)
            {
                throw std::logic_error("model '" + context_.label + "' reads key '" +
                                       std::string(key) + "' as " + toString(expected) +
                                       " but declared it as " + toString(value.key.type()));
            }
            if (!value.present)
            {
                throw std::logic_error("model '" + context_.label + "' reads optional key '" +
                                       std::string(key) + "' without checking has()");
            }
            return value;
        }
    }
    std::vector<std::string> declared;
    for (const Value& value : values_)
    {
        declared.push_back(value.key.name());
    }
    throw std::logic_error("model '" + context_.label + "' reads undeclared key '" +
                           std::string(key) + "' (declared: " + joinSorted(declared) + "). " +
                           didYouMean(key, declared));
}

double Params::real(std::string_view key) const { return get(key, ValueType::Real).real; }
long Params::integer(std::string_view key) const { return get(key, ValueType::Integer).integer; }
bool Params::boolean(std::string_view key) const { return get(key, ValueType::Bool).boolean; }
const std::string& Params::word(std::string_view key) const { return get(key, ValueType::Word).text; }
const std::string& Params::string(std::string_view key) const { return get(key, ValueType::String).text; }
const std::vector<double>& Params::vector(std::string_view key) const { return get(key, ValueType::Vector).reals; }
const std::vector<double>& Params::realList(std::string_view key) const { return get(key, ValueType::RealList).reals; }
const std::vector<std::string>& Params::wordList(std::string_view key) const { return get(key, ValueType::WordList).words; }
const std::vector<std::string>& Params::stringList(std::string_view key) const { return get(key, ValueType::StringList).words; }
const std::vector<std::vector<double>>& Params::vectorList(std::string_view key) const { return get(key, ValueType::VectorList).vectors; }
const Dictionary& Params::dict(std::string_view key) const { return *get(key, ValueType::Dict).dict; }

bool Params::has(std::string_view key) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            return value.present;
        }
    }
    throw std::logic_error("model '" + context_.label + "' asks for undeclared key '" +
                           std::string(key) + "'");
}

bool Params::given(std::string_view key) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            return value.given;
        }
    }
    throw std::logic_error("model '" + context_.label + "' asks for undeclared key '" +
                           std::string(key) + "'");
}

SourceLocation Params::location(std::string_view key) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            return value.where;
        }
    }
    return source_->location();
}

SourceLocation Params::location(std::string_view key, std::size_t index) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            return index < value.elements.size() ? value.elements[index] : value.where;
        }
    }
    return source_->location();
}

void Params::fail(std::string_view key, const std::string& message,
                  std::vector<std::string> notes) const
{
    throw InputError(location(key), message, std::move(notes));
}

void Params::fail(std::string_view key, std::size_t index, const std::string& message,
                  std::vector<std::string> notes) const
{
    throw InputError(location(key, index), message, std::move(notes));
}

} // namespace sph
