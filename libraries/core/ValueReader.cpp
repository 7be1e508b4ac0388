#include "ValueReader.hpp"

#include "Suggest.hpp"

#include "Format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph
{

void ValueReader::read(const std::vector<Item>& items, const SourceLocation& keyWhere,
                       bool isDefault, double& real, long& integer, bool& boolean,
                       std::string& text, std::vector<double>& reals,
                       std::vector<std::string>& words, std::vector<std::vector<double>>& vectors)
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
            checkDistinct(element, words);
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
            vectors.push_back(
                vectorValue(element, key_.fixedSize() ? key_.fixedSize() : context_.dimension));
        }
        break;
    case ValueType::Dict:
        throw mismatch(item);
    }
}

std::string ValueReader::expected() const
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
        return "a " + key_.typeText();
    }
}

InputError ValueReader::mismatch(const Item& item) const
{
    return InputError(item.location(),
                      "'" + key_.name() + "' in '" + owner_ + "' must be " + expected() +
                          ", found " + item.describe(),
                      notes());
}

std::string ValueReader::example(int n)
{
    std::string text = "(";
    for (int i = 0; i < n; ++i)
    {
        text += i ? " 0" : "0";
    }
    return text + ")";
}

std::vector<std::string> ValueReader::notes() const
{
    std::vector<std::string> result;
    const std::string doc = key_.doc(context_.dimension);
    if (!doc.empty())
    {
        result.push_back("'" + key_.name() + "': " + doc + ".");
    }
    if (isDefault_)
    {
        result.push_back("(This is the declared default of the key: a bug in the model.)");
    }
    return result;
}

double ValueReader::number(const Item& item) const
{
    if (item.kind() != Item::Kind::Number)
    {
        throw mismatch(item);
    }
    checkRange(item, item.number());
    return item.number();
}

long ValueReader::wholeNumber(const Item& item) const
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

void ValueReader::checkRange(const Item& item, double value) const
{
    checkNormal(item, value);
    if (!key_.inRange(value))
    {
        throw InputError(item.location(),
                         key_.name() + " = " + item.text() + " must lie in " + key_.rangeText(),
                         notes());
    }
}

void ValueReader::checkNormal(const Item& item, double value) const
{
    // A subnormal number (4.9e-324) is no physical value of any key: it holds fewer digits than
    // written and is zero for most arithmetic (yieldStress 4.9e-324 was taken; issue 31).
    if (value != 0.0 && std::abs(value) < std::numeric_limits<double>::min())
    {
        throw InputError(item.location(),
                         key_.name() + " = " + item.text() + " is below the smallest normal "
                                                             "number (" +
                             formatNumber(std::numeric_limits<double>::min()) +
                             "): is the exponent right?",
                         notes());
    }
}

bool ValueReader::truthValue(const Item& item) const
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

std::string ValueReader::wordValue(const Item& item) const
{
    if (item.kind() != Item::Kind::Word)
    {
        throw mismatch(item);
    }
    const auto& allowed = key_.allowedWords();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), item.text()) == allowed.end())
    {
        std::vector<std::string> lines{"Valid values for '" + key_.name() +
                                       "': " + joinSorted(allowed)};
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
    if (key_.namesBodies())
    {
        checkBody(item);
    }
    return item.text();
}

void ValueReader::checkBody(const Item& item) const
{
    const std::vector<std::string>& bodies = context_.bodies;
    if (bodies.empty() || std::find(bodies.begin(), bodies.end(), item.text()) != bodies.end())
    {
        return; // not known here (e.g. sphParticles), or one of them
    }
    std::vector<std::string> lines{"Bodies (" + std::to_string(bodies.size()) +
                                   "): " + joinSorted(bodies)};
    const std::string hint = didYouMean(item.text(), bodies);
    lines.push_back(hint.empty() ? "The bodies are the top-level entries of system/particlesDict."
                                 : hint);
    throw InputError(item.location(),
                     "no body named '" + item.text() + "' ('" + key_.name() + "' in '" + owner_ +
                         "')",
                     lines);
}

void ValueReader::checkDistinct(const Item& item, const std::vector<std::string>& words) const
{
    if (!key_.distinctNames() ||
        std::find(words.begin(), words.end() - 1, words.back()) == words.end() - 1)
    {
        return;
    }
    std::vector<std::string> lines{"'" + key_.name() + "' lists each name once; is another "
                                   "name meant here?"};
    if (key_.namesBodies() && !context_.bodies.empty())
    {
        lines.push_back("Bodies (" + std::to_string(context_.bodies.size()) +
                        "): " + joinSorted(context_.bodies));
    }
    for (const std::string& note : notes())
    {
        lines.push_back(note);
    }
    throw InputError(item.location(),
                     "'" + item.text() + "' appears twice in '" + key_.name() + "' of '" +
                         owner_ + "'",
                     lines);
}

std::string ValueReader::stringValue(const Item& item) const
{
    if (item.kind() != Item::Kind::String && item.kind() != Item::Kind::Word)
    {
        throw mismatch(item);
    }
    return item.text();
}

const std::vector<Item>& ValueReader::listItems(const Item& item) const
{
    if (!item.isList())
    {
        throw InputError(item.location(),
                         "'" + key_.name() + "' in '" + owner_ +
                             "' must be a list ( ... ), found " + item.describe(),
                         notes());
    }
    return item.items();
}

std::vector<double> ValueReader::vectorValue(const Item& item, int components) const
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
        checkNormal(element, element.number());
        result.push_back(element.number());
    }
    return result;
}

} // namespace sph
