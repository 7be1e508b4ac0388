// Params: the validated values of one dictionary (declared in Schema.hpp).
#include "InputError.hpp"
#include "Schema.hpp"
#include "Suggest.hpp"

#include <algorithm>
#include <stdexcept>

namespace sph
{

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

double Params::real(std::string_view key) const
{
    return get(key, ValueType::Real).real;
}
long Params::integer(std::string_view key) const
{
    return get(key, ValueType::Integer).integer;
}
bool Params::boolean(std::string_view key) const
{
    return get(key, ValueType::Bool).boolean;
}
const std::string& Params::word(std::string_view key) const
{
    return get(key, ValueType::Word).text;
}
const std::string& Params::string(std::string_view key) const
{
    return get(key, ValueType::String).text;
}
const std::vector<double>& Params::vector(std::string_view key) const
{
    return get(key, ValueType::Vector).reals;
}
const std::vector<double>& Params::realList(std::string_view key) const
{
    return get(key, ValueType::RealList).reals;
}
const std::vector<std::string>& Params::wordList(std::string_view key) const
{
    return get(key, ValueType::WordList).words;
}
const std::vector<std::string>& Params::stringList(std::string_view key) const
{
    return get(key, ValueType::StringList).words;
}
const std::vector<std::vector<double>>& Params::vectorList(std::string_view key) const
{
    return get(key, ValueType::VectorList).vectors;
}
const Dictionary& Params::dict(std::string_view key) const
{
    return *get(key, ValueType::Dict).dict;
}

std::size_t Params::bodyIndex(std::string_view key) const
{
    return bodyIndices(key).front();
}

std::vector<std::size_t> Params::bodyIndices(std::string_view key) const
{
    const auto value = std::find_if(values_.begin(), values_.end(),
                                    [&](const Value& v) { return v.key.name() == key; });
    if (value == values_.end() || !value->key.namesBodies() || context_.bodies.empty())
    {
        throw std::logic_error("model '" + context_.label + "' reads key '" + std::string(key) +
                               "' as body names, but " +
                               (value == values_.end() || !value->key.namesBodies()
                                    ? "did not declare it with Key::body or Key::bodyList"
                                    : "the case's bodies were not given to the validation"));
    }
    const Value& read = get(key, value->key.type()); // checks that it has a value
    const std::vector<std::string> names =
        read.key.type() == ValueType::Word ? std::vector<std::string>{read.text} : read.words;
    std::vector<std::size_t> result;
    for (const std::string& name : names)
    {
        // Validation checked every name against these bodies.
        const auto it = std::find(context_.bodies.begin(), context_.bodies.end(), name);
        result.push_back(static_cast<std::size_t>(it - context_.bodies.begin()));
    }
    return result;
}

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

const std::string& Params::written(std::string_view key) const
{
    for (const Value& value : values_)
    {
        if (value.key.name() == key)
        {
            return value.written;
        }
    }
    throw std::logic_error("model '" + context_.label + "' asks for undeclared key '" +
                           std::string(key) + "'");
}

std::string Params::summary() const
{
    std::string text;
    for (const Value& value : values_)
    {
        if (value.present)
        {
            text += (text.empty() ? "" : ", ") + value.key.name() + "=" + value.written;
        }
    }
    return text;
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
