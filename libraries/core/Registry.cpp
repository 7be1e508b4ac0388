#include "Registry.hpp"

#include "Suggest.hpp"

#include <dlfcn.h>

#include <algorithm>

namespace sph
{

std::vector<int> ModelRecord::dimensions() const
{
    std::vector<int> result;
    for (const auto& [dimension, factory] : factories)
    {
        result.push_back(dimension);
    }
    return result;
}

RegistryStore& RegistryStore::instance()
{
    // Deliberately leaked: registrations from libraries unloaded late must still find it.
    static RegistryStore* store = new RegistryStore();
    return *store;
}

namespace
{

std::string libraryOf(const void* address)
{
    Dl_info info{};
    if (address && dladdr(address, &info) && info.dli_fname)
    {
        return info.dli_fname;
    }
    return "unknown library";
}

} // namespace

void RegistryStore::add(const std::string& family, const std::string& name, int dimension,
                        std::string description, std::function<Schema()> schema,
                        std::string sourceFile, std::shared_ptr<const void> factory,
                        const void* codeAddress, std::vector<FieldSpec> fields)
{
    const std::string library = libraryOf(codeAddress);
    ModelRecord& record = families_[family][name];
    if (record.name.empty())
    {
        record.family = family;
        record.name = name;
        record.description = std::move(description);
        record.sourceFile = std::move(sourceFile);
        record.library = library;
        record.schema = std::move(schema);
        record.fields = std::move(fields);
    }
    else if (record.sourceFile != sourceFile || record.library != library ||
             record.factories.count(dimension))
    {
        const std::string message = family + " type '" + name + "' is registered twice: in " +
                                    record.sourceFile + " (" + record.library + ") and in " +
                                    sourceFile + " (" + library + ")";
        if (std::find(conflicts_.begin(), conflicts_.end(), message) == conflicts_.end())
        {
            conflicts_.push_back(message);
        }
        return; // the first registration stays in force
    }
    record.factories[dimension] = std::move(factory);
}

const ModelRecord* RegistryStore::find(const std::string& family, const std::string& name) const
{
    const auto f = families_.find(family);
    if (f == families_.end())
    {
        return nullptr;
    }
    const auto m = f->second.find(name);
    return m == f->second.end() ? nullptr : &m->second;
}

std::vector<std::string> RegistryStore::names(const std::string& family, int dimension) const
{
    std::vector<std::string> result;
    const auto f = families_.find(family);
    if (f == families_.end())
    {
        return result;
    }
    for (const auto& [name, record] : f->second)
    {
        if (dimension == 0 || record.factories.count(dimension))
        {
            result.push_back(name);
        }
    }
    return result; // std::map keeps them sorted
}

std::vector<std::string> RegistryStore::families() const
{
    std::vector<std::string> result;
    for (const auto& [family, models] : families_)
    {
        result.push_back(family);
    }
    return result;
}

std::vector<std::string> RegistryStore::takeConflicts()
{
    std::vector<std::string> result;
    result.swap(conflicts_);
    return result;
}

InputError unknownModelError(const std::string& family, const std::string& name,
                             const SourceLocation& where, int dimension, bool caseLibraries)
{
    const RegistryStore& store = RegistryStore::instance();
    const std::vector<std::string> valid = store.names(family, dimension);
    std::vector<std::string> notes{"Valid " + family + " types (" + std::to_string(valid.size()) +
                                   "): " + joinSorted(valid)};
    const ModelRecord* other = store.find(family, name);
    std::string message = "unknown " + family + " type '" + name + "'";
    if (other && dimension > 0)
    {
        std::string dims;
        for (int d : other->dimensions())
        {
            dims += (dims.empty() ? "" : ", ") + std::to_string(d) + "D";
        }
        message = family + " type '" + name + "' is not available in " +
                  std::to_string(dimension) + "D";
        notes.push_back("'" + name + "' exists for " + dims + ".");
        return InputError(where, message, notes);
    }
    std::string hint = didYouMean(name, valid);
    if (caseLibraries)
    {
        hint += std::string(hint.empty() ? "" : "  ") +
                "(Types from your own libraries need them listed in system/controlDict 'libs'.)";
    }
    if (!hint.empty())
    {
        notes.push_back(hint);
    }
    return InputError(where, message, notes);
}

} // namespace sph
