// Schema: validation of a dictionary against declared keys, and -listTypes lines (Key.cpp:
// the keys themselves; Params.cpp: the validated values).
#include "Schema.hpp"

#include "DictionaryParser.hpp"
#include "InputError.hpp"
#include "Suggest.hpp"
#include "ValueReader.hpp"

#include <algorithm>
#include <stdexcept>

namespace sph
{

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

Params Schema::validate(const Dictionary& dict, const std::string& label, int dimension,
                        TypeEntry type) const
{
    ValidationContext context;
    context.dimension = dimension;
    context.label = label;
    if (type == TypeEntry::isKey)
    {
        context.ignoredKeys.clear();
    }
    return validate(dict, context);
}

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
        if (context.otherModelsWith)
        {
            const std::vector<std::string> owners = context.otherModelsWith(entry.key());
            if (!owners.empty())
            {
                notes.push_back("'" + entry.key() + "' is a key of " + joinSorted(owners) +
                                ", not of " + label + ": is the type right?");
            }
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
                value.written = "{ ... }";
            }
            else if (entry->isDict())
            {
                throw InputError(entry->keyLocation(),
                                 "'" + key.name() + "' in '" + owner + "' must be " +
                                     reader.expected() + ", found a dictionary { ... }",
                                 {"'" + key.name() + "': " + key.doc(context.dimension) + "."});
            }
            else
            {
                reader.read(entry->items(), entry->keyLocation(), false, value.real, value.integer,
                            value.boolean, value.text, value.reals, value.words, value.vectors);
                value.written = entry->items().front().toText();
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
            value.written = *key.defaultText();
            auto source = std::make_shared<const SourceText>("<default of '" + key.name() + "'>",
                                                             *key.defaultText());
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
                reader.read(items, dict.location(), true, value.real, value.integer, value.boolean,
                            value.text, value.reals, value.words, value.vectors);
            }
        }
        else if (key.required())
        {
            const std::vector<std::string> needed = requiredNames();
            SourceLocation where = dict.location();
            throw InputError(where, "missing required key '" + key.name() + "' in '" + owner + "'",
                             {"(" + label + " needs: " + joinSorted(needed) + ")",
                              "'" + key.name() + "': " + key.doc(context.dimension) + " (" +
                                  reader.expected() +
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
        std::string line = key.name() + "  (" + key.typeText();
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
        if (key.distinctNames())
        {
            line += ", each name once";
        }
        line += ")  " + key.doc();
        lines.push_back(line);
    }
    return lines;
}

} // namespace sph
