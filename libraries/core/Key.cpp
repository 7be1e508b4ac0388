// Key: one declared dictionary key (declared in Schema.hpp).
#include "Schema.hpp"

#include "Format.hpp"
#include "Registry.hpp"

#include <cmath>

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

Key::Key(std::string name, ValueType type, std::string doc)
    : name_(std::move(name)), type_(type), doc_(std::move(doc))
{
}

Key Key::real(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Real, std::move(doc)};
}
Key Key::integer(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Integer, std::move(doc)};
}
Key Key::boolean(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Bool, std::move(doc)};
}
Key Key::word(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Word, std::move(doc)};
}
Key Key::string(std::string name, std::string doc)
{
    return {std::move(name), ValueType::String, std::move(doc)};
}
Key Key::vector(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Vector, std::move(doc)};
}
Key Key::realList(std::string name, std::string doc)
{
    return {std::move(name), ValueType::RealList, std::move(doc)};
}
Key Key::wordList(std::string name, std::string doc)
{
    return {std::move(name), ValueType::WordList, std::move(doc)};
}
Key Key::stringList(std::string name, std::string doc)
{
    return {std::move(name), ValueType::StringList, std::move(doc)};
}
Key Key::vectorList(std::string name, std::string doc)
{
    return {std::move(name), ValueType::VectorList, std::move(doc)};
}
Key Key::dict(std::string name, std::string doc)
{
    return {std::move(name), ValueType::Dict, std::move(doc)};
}
Key Key::body(std::string name, std::string doc)
{
    Key key(std::move(name), ValueType::Word, std::move(doc));
    key.bodies_ = true;
    return key;
}
Key Key::bodyList(std::string name, std::string doc)
{
    Key key(std::move(name), ValueType::WordList, std::move(doc));
    key.bodies_ = true;
    return key;
}

std::string Key::typeText() const
{
    if (bodies_)
    {
        return type_ == ValueType::Word ? "body name" : "list of body names";
    }
    return toString(type_);
}

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

Key& Key::distinct()
{
    distinct_ = true;
    return *this;
}

Key& Key::selects(std::string family)
{
    family_ = std::move(family);
    return *this;
}

std::string Key::doc(int dimension) const
{
    if (family_.empty())
    {
        return doc_;
    }
    // Looked up now, not when the schema was declared: libraries load in between. A
    // dimension-independent family has no models by dimension: then all of them.
    const RegistryStore& store = RegistryStore::instance();
    std::vector<std::string> names = store.names(family_, dimension);
    if (names.empty())
    {
        names = store.names(family_);
    }
    std::string types;
    for (const std::string& name : names)
    {
        types += (types.empty() ? "" : " | ") + name;
    }
    // The doc shows the syntax, "{ type ...; }": the types replace its "...".
    const std::string placeholder = "type ...";
    const std::size_t at = doc_.find(placeholder);
    if (at == std::string::npos)
    {
        return doc_ + " { type " + types + "; ... }";
    }
    return doc_.substr(0, at) + "type " + types + doc_.substr(at + placeholder.size());
}

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

} // namespace sph
