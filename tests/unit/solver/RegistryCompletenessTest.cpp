// Catches models dropped by the linker or a registration line lost in an edit: the registered
// names of every family, per dimension, are exactly the expected ones.
#include "core/LibraryLoader.hpp"
#include "core/Registry.hpp"
#include "support/TestSupport.hpp"

#include <map>
#include <set>

using namespace sph;

namespace
{

using Names = std::set<std::string>;

// The models of sphSolid's own libraries (plugins loaded by other tests do not count).
Names ownModels(const std::string& family, int dimension)
{
    const RegistryStore& store = RegistryStore::instance();
    Names names;
    for (const auto& name : store.names(family, dimension))
    {
        const std::filesystem::path library = store.find(family, name)->library;
        if (std::filesystem::equivalent(library.parent_path(), LibraryLoader::libraryDirectory()))
        {
            names.insert(name);
        }
    }
    return names;
}

// family -> dimension -> names (dimension 0: dimension-independent family)
const std::map<std::string, std::map<int, Names>>& expected()
{
    static const Names everyScheme{"gradF", "hourglass", "none", "oneSided", "vidal"};
    static const std::map<std::string, std::map<int, Names>> table{
        {"kernel", {{0, {"cubicSpline", "quinticSpline", "wendlandC2"}}}},
        {"material",
         {{1, {"hencky", "j2Plasticity", "linearElastic", "neoHookean", "stVenantKirchhoff"}},
          {2, {"druckerPrager", "hencky", "j2Plasticity", "linearElastic", "neoHookean", "stVenantKirchhoff"}},
          {3, {"druckerPrager", "hencky", "j2Plasticity", "linearElastic", "neoHookean", "stVenantKirchhoff"}}}},
        {"formulation",
         {{1, {"totalLagrangian", "updatedLagrangian"}},
          {2, {"totalLagrangian", "updatedLagrangian"}},
          {3, {"totalLagrangian", "updatedLagrangian"}}}},
        {"stabilisation", {{1, everyScheme}, {2, everyScheme}, {3, everyScheme}}},
        {"contact", {{1, {"none", "repulsion"}}, {2, {"none", "repulsion"}}, {3, {"none", "repulsion"}}}},
        {"timeIntegration", {{1, {"leapfrog"}}, {2, {"leapfrog"}}, {3, {"leapfrog"}}}},
        {"artificialViscosity",
         {{1, {"monaghan", "none"}}, {2, {"monaghan", "none"}}, {3, {"monaghan", "none"}}}},
        {"wall", {{1, {"box", "plane"}}, {2, {"box", "plane"}}, {3, {"box", "plane"}}}},
        {"functionObject",
         {{1, {"energy", "exactSolution", "extent", "oscillation", "probes", "snapshot", "stabilityMonitor",
               "staticState", "wallForce"}},
          {2, {"energy", "extent", "failureLine", "oscillation", "probes", "snapshot", "stabilityMonitor",
               "staticState", "surfaceProfile", "wallForce"}},
          {3, {"energy", "extent", "oscillation", "probes", "snapshot", "stabilityMonitor", "staticState",
               "surfaceProfile", "wallForce"}}}},
        {"region",
         {{1, {"all", "box", "halfSpace", "nearest", "sphere"}},
          {2, {"all", "box", "halfSpace", "nearest", "sphere"}},
          {3, {"all", "box", "halfSpace", "nearest", "sphere"}}}},
        {"velocityField",
         {{1, {"uniform"}}, {2, {"cantileverMode", "rotation", "uniform"}},
          {3, {"cantileverMode", "rotation", "twist", "uniform"}}}},
        {"stressField", {{1, {"geostatic"}}, {2, {"geostatic"}}, {3, {"geostatic"}}}},
        {"displacementField",
         {{1, {"affine", "checkerboard", "random"}},
          {2, {"affine", "checkerboard", "random"}},
          {3, {"affine", "checkerboard", "random"}}}},
        {"generator",
         {{1, {"box", "line", "vtu"}},
          {2, {"annulus", "box", "disk", "polygon", "vtu"}},
          {3, {"box", "cylinder", "vtu"}}}},
    };
    return table;
}

} // namespace

TEST_CASE("every family registers exactly the expected models", "[registry]")
{
    test::loadModelLibraries();
    const RegistryStore& store = RegistryStore::instance();
    for (const auto& [family, byDimension] : expected())
    {
        for (const auto& [dimension, names] : byDimension)
        {
            INFO(family << " in " << dimension << "D");
            CHECK(ownModels(family, dimension) == names);
        }
    }
    // No family nobody expects (a test-only family does not load here).
    for (const auto& family : store.families())
    {
        if (!ownModels(family, 0).empty())
        {
            INFO(family);
            CHECK(expected().count(family) == 1);
        }
    }
}

TEST_CASE("every registered model documents itself and its keys", "[registry]")
{
    test::loadModelLibraries();
    const RegistryStore& store = RegistryStore::instance();
    for (const auto& family : store.families())
    {
        for (const auto& name : store.names(family))
        {
            INFO(family << " " << name);
            const ModelRecord* record = store.find(family, name);
            CHECK(record->description.size() > 20);
            CHECK_THAT(record->library, Catch::Contains("libsph"));
            const Schema schema = record->schema();
            for (const Key& key : schema.keys())
            {
                CHECK(!key.doc().empty());
            }
        }
    }
}
