#include "ModelListing.hpp"

#include "InputError.hpp"
#include "Registry.hpp"
#include "Suggest.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>

namespace sph
{

void listTypes(std::ostream& out, const std::string& family, const SourceLocation& where)
{
    RegistryStore& store = RegistryStore::instance();
    const std::vector<std::string> families = store.families();
    if (!family.empty() && std::find(families.begin(), families.end(), family) == families.end())
    {
        std::vector<std::string> notes{"Families: " + joinSorted(families)};
        const std::string hint = didYouMean(family, families);
        if (!hint.empty())
        {
            notes.push_back(hint);
        }
        throw InputError(where, "-listTypes: unknown family '" + family + "'", notes);
    }
    for (const std::string& name : families)
    {
        if (!family.empty() && name != family)
        {
            continue;
        }
        const auto models = store.names(name);
        out << name << " (" << models.size() << " type" << (models.size() == 1 ? "" : "s")
            << ")\n";
        for (const std::string& model : models)
        {
            const ModelRecord* record = store.find(name, model);
            std::string dims;
            for (int d : record->dimensions())
            {
                dims += d == 0 ? "any" : std::to_string(d) + "D ";
            }
            out << "  " << model << "\n      " << record->description << "\n      ["
                << std::filesystem::path(record->library).filename().string() << ", "
                << (dims == "1D 2D 3D " ? "1D/2D/3D" : dims) << "]\n";
            const auto keys = record->schema().describe();
            if (keys.empty())
            {
                out << "      keys: none\n";
            }
            for (const auto& key : keys)
            {
                out << "      " << key << "\n";
            }
            if (!record->fields.empty())
            {
                out << "      per-particle fields (written to VTK/ as described in the README):\n";
            }
            for (const auto& field : record->fields)
            {
                out << "        " << field.describe() << "\n";
            }
        }
        out << "\n";
    }
}

} // namespace sph
