#include "Dictionary.hpp"

#include "InputError.hpp"

#include <cstdio>

namespace sph
{

// ---------------------------------------------------------------------------------------- Item

Item Item::word(std::string text, SourceLocation where)
{
    Item item;
    item.kind_ = Kind::Word;
    item.text_ = std::move(text);
    item.location_ = std::move(where);
    return item;
}

Item Item::number(std::string text, double value, SourceLocation where)
{
    Item item;
    item.kind_ = Kind::Number;
    item.text_ = std::move(text);
    item.number_ = value;
    item.location_ = std::move(where);
    return item;
}

Item Item::string(std::string text, SourceLocation where)
{
    Item item;
    item.kind_ = Kind::String;
    item.text_ = std::move(text);
    item.location_ = std::move(where);
    return item;
}

Item Item::list(std::vector<Item> items, SourceLocation open)
{
    Item item;
    item.kind_ = Kind::List;
    item.items_ = std::move(items);
    item.location_ = std::move(open);
    return item;
}

std::string Item::describe() const
{
    switch (kind_)
    {
    case Kind::Word:
        return "word '" + text_ + "'";
    case Kind::Number:
        return "number " + text_;
    case Kind::String:
        return "string \"" + text_ + "\"";
    case Kind::List:
        return "a list of " + std::to_string(items_.size()) + " item" +
               (items_.size() == 1 ? "" : "s");
    }
    return {};
}

std::string Item::toText() const
{
    switch (kind_)
    {
    case Kind::Word:
    case Kind::Number:
        return text_;
    case Kind::String:
        return "\"" + text_ + "\"";
    case Kind::List:
    {
        std::string text = "(";
        for (std::size_t i = 0; i < items_.size(); ++i)
        {
            text += (i ? " " : "") + items_[i].toText();
        }
        return text + ")";
    }
    }
    return {};
}

// --------------------------------------------------------------------------------------- Entry

Entry::Entry(std::string key, SourceLocation keyLocation, std::vector<Item> value)
    : key_(std::move(key)), keyLocation_(std::move(keyLocation)), items_(std::move(value))
{
}

Entry::Entry(std::string key, SourceLocation keyLocation, std::unique_ptr<Dictionary> dict)
    : key_(std::move(key)), keyLocation_(std::move(keyLocation)), dict_(std::move(dict))
{
}

Entry::Entry(const Entry& other)
    : key_(other.key_), keyLocation_(other.keyLocation_), items_(other.items_),
      dict_(other.dict_ ? std::make_unique<Dictionary>(*other.dict_) : nullptr),
      overridable_(other.overridable_), referenced_(other.referenced_)
{
}

Entry::Entry(Entry&&) noexcept = default;
Entry& Entry::operator=(Entry&&) noexcept = default;
Entry::~Entry() = default;

Entry& Entry::operator=(const Entry& other)
{
    if (this != &other)
    {
        Entry copy(other);
        *this = std::move(copy);
    }
    return *this;
}

SourceLocation Entry::valueLocation() const
{
    if (dict_)
    {
        return dict_->location();
    }
    if (!items_.empty())
    {
        return items_.front().location();
    }
    return keyLocation_;
}

void Entry::setItems(std::vector<Item> items)
{
    dict_.reset();
    items_ = std::move(items);
}

// ---------------------------------------------------------------------------------- Dictionary

Dictionary::Dictionary(std::string name, SourceLocation location)
    : name_(std::move(name)), location_(std::move(location)), endLocation_(location_)
{
}

Dictionary::Dictionary(const Dictionary& other)
    : name_(other.name_), location_(other.location_), endLocation_(other.endLocation_),
      parent_(other.parent_), entries_(other.entries_)
{
    for (Entry& entry : entries_)
    {
        if (entry.isDict())
        {
            entry.dict().reparent(this, entry.key());
        }
    }
}

Dictionary& Dictionary::operator=(const Dictionary& other)
{
    if (this != &other)
    {
        name_ = other.name_;
        location_ = other.location_;
        endLocation_ = other.endLocation_;
        parent_ = other.parent_;
        entries_ = other.entries_;
        for (Entry& entry : entries_)
        {
            if (entry.isDict())
            {
                entry.dict().reparent(this, entry.key());
            }
        }
    }
    return *this;
}

Dictionary::~Dictionary() = default;

std::string Dictionary::displayName() const
{
    if (!name_.empty())
    {
        return name_;
    }
    return location_.fileName();
}

const Dictionary& Dictionary::topLevel() const
{
    const Dictionary* dict = this;
    while (dict->parent_)
    {
        dict = dict->parent_;
    }
    return *dict;
}

const Entry* Dictionary::find(std::string_view key) const
{
    for (const Entry& entry : entries_)
    {
        if (entry.key() == key)
        {
            return &entry;
        }
    }
    return nullptr;
}

Entry* Dictionary::find(std::string_view key)
{
    return const_cast<Entry*>(static_cast<const Dictionary*>(this)->find(key));
}

std::vector<std::string> Dictionary::keys() const
{
    std::vector<std::string> result;
    result.reserve(entries_.size());
    for (const Entry& entry : entries_)
    {
        result.push_back(entry.key());
    }
    return result;
}

Entry& Dictionary::add(Entry entry)
{
    if (Entry* existing = find(entry.key()))
    {
        if (!existing->overridable())
        {
            throw InputError(entry.keyLocation(),
                             "duplicate key '" + entry.key() + "' in '" + displayName() + "'",
                             {"First defined at " + existing->keyLocation().prefix() +
                              ". Each key may appear once per dictionary."});
        }
        *existing = std::move(entry);
        if (existing->isDict())
        {
            existing->dict().reparent(this, existing->key());
        }
        return *existing;
    }
    entries_.push_back(std::move(entry));
    Entry& added = entries_.back();
    if (added.isDict())
    {
        added.dict().reparent(this, added.key());
    }
    return added;
}

const Entry* Dictionary::lookupScoped(std::string_view path) const
{
    const std::size_t dot = path.find('.');
    const std::string_view first = path.substr(0, dot);
    const Entry* entry = nullptr;
    for (const Dictionary* scope = this; scope && !entry; scope = scope->parent_)
    {
        entry = scope->find(first);
    }
    if (!entry || dot == std::string_view::npos)
    {
        return entry;
    }
    if (!entry->isDict())
    {
        return nullptr;
    }
    return entry->dict().lookupScoped(path.substr(dot + 1));
}

std::vector<std::string> Dictionary::visibleKeys() const
{
    std::vector<std::string> result;
    for (const Dictionary* scope = this; scope; scope = scope->parent_)
    {
        for (const Entry& entry : scope->entries_)
        {
            result.push_back(entry.key());
        }
    }
    return result;
}

void Dictionary::reparent(const Dictionary* parent, const std::string& name)
{
    parent_ = parent;
    name_ = parent && !parent->name_.empty() ? parent->name_ + "/" + name : name;
    for (Entry& entry : entries_)
    {
        if (entry.isDict())
        {
            entry.dict().reparent(this, entry.key());
        }
    }
}

} // namespace sph
