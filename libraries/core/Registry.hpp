#pragma once
// Runtime selection by name (design guide §5).
//
// Every model family has an interface class `Base` that declares
//     static constexpr const char* family = "material";   // used in messages and -listTypes
//     static constexpr int dimension = D;                  // 0 for dimension-independent families
//     struct Args { ... };                                 // what the solver passes at construction
// and every model `M` declares
//     static std::string description();                    // one paragraph for -listTypes
//     static Schema schema();                              // its dictionary keys
//     static std::vector<FieldSpec> fields();              // optional: its per-particle fields
//     M(const Params& params, const Base::Args& args);
// and registers itself in ONE line at the bottom of its .cpp:
//     SPH_REGISTER_MODEL(Kernel, CubicSpline, "cubicSpline");          // dimension-independent
//     SPH_REGISTER_DIM_MODEL(Material, NeoHookean, "neoHookean");       // Dim = 1, 2, 3
//     SPH_REGISTER_DIM_MODEL_FOR(Generator, Disk, "disk", 2);           // only some dimensions
// A family whose models appear in the run log derives Base from RegisteredModel: a model's
// summary, "name(key=value, ...)", then comes from its registered name and its params.
//
// The records live in one process-wide store inside libsphCore, so models from plugin
// libraries loaded with dlopen land in the same tables as the built-in ones. A duplicate name
// cannot throw during dlopen; it is recorded and reported by the loader, naming both sources.

#include "FieldSpec.hpp"
#include "InputError.hpp"
#include "RegisteredModel.hpp"
#include "Schema.hpp"
#include "Suggest.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace sph
{

struct ModelRecord
{
    std::string family;
    std::string name;
    std::string description;
    std::string sourceFile;
    std::string library; // the shared object that registered it
    std::function<Schema()> schema;
    std::vector<FieldSpec> fields; // the per-particle fields the model declares
    std::map<int, std::shared_ptr<const void>> factories; // by dimension (0: any)

    std::vector<int> dimensions() const;
};

class RegistryStore
{
public:
    static RegistryStore& instance();

    void add(const std::string& family, const std::string& name, int dimension,
             std::string description, std::function<Schema()> schema, std::string sourceFile,
             std::shared_ptr<const void> factory, const void* codeAddress,
             std::vector<FieldSpec> fields = {});

    const ModelRecord* find(const std::string& family, const std::string& name) const;
    // Sorted names of a family; with dimension > 0 only those available in that dimension.
    std::vector<std::string> names(const std::string& family, int dimension = 0) const;
    std::vector<std::string> families() const;
    // Duplicate registrations seen since the last call (one message each).
    std::vector<std::string> takeConflicts();

private:
    RegistryStore() = default;
    std::map<std::string, std::map<std::string, ModelRecord>> families_;
    std::vector<std::string> conflicts_;
};

// Typed view of one family.
template <class Base>
class Registry
{
public:
    using Args = typename Base::Args;
    using Factory = std::function<std::unique_ptr<Base>(const Params&, const Args&)>;

    static void add(const std::string& name, std::string description,
                    std::function<Schema()> schema, std::string sourceFile, Factory factory,
                    const void* codeAddress, std::vector<FieldSpec> fields = {})
    {
        RegistryStore::instance().add(Base::family, name, Base::dimension, std::move(description),
                                      std::move(schema), std::move(sourceFile),
                                      std::make_shared<const Factory>(std::move(factory)),
                                      codeAddress, std::move(fields));
    }

    static std::vector<std::string> names()
    {
        return RegistryStore::instance().names(Base::family, Base::dimension);
    }

    static const ModelRecord* find(const std::string& name)
    {
        const ModelRecord* record = RegistryStore::instance().find(Base::family, name);
        if (record && record->factories.count(Base::dimension))
        {
            return record;
        }
        return nullptr;
    }

    // Builds model `name` from already validated params; a RegisteredModel learns its name and
    // parameters (for its summary).
    static std::unique_ptr<Base> create(const std::string& name, const Params& params,
                                        const Args& args)
    {
        const ModelRecord* record = find(name);
        if (!record)
        {
            throw std::logic_error(std::string("no ") + Base::family + " model '" + name + "'");
        }
        const auto& factory =
            *static_cast<const Factory*>(record->factories.at(Base::dimension).get());
        std::unique_ptr<Base> model = factory(params, args);
        if constexpr (std::is_base_of_v<RegisteredModel, Base>)
        {
            RegisteredModel& registered = *model;
            registered.typeName_ = name;
            registered.parameters_ = params.summary();
        }
        return model;
    }
};

// The fields a model declares (none unless it has `static std::vector<FieldSpec> fields()`).
template <class Model>
std::vector<FieldSpec> declaredFields()
{
    if constexpr (requires { Model::fields(); })
    {
        return Model::fields();
    }
    else
    {
        return {};
    }
}

template <class Base, class Model>
struct Registration
{
    Registration(const char* name, const char* sourceFile)
    {
        Registry<Base>::add(
            name, Model::description(), &Model::schema, sourceFile,
            [](const Params& params, const typename Base::Args& args) -> std::unique_ptr<Base> {
                return std::make_unique<Model>(params, args);
            },
            reinterpret_cast<const void*>(&Model::description), declaredFields<Model>());
    }
};

template <template <int> class BaseT, template <int> class ModelT, int... Dims>
struct DimRegistration
{
    DimRegistration(const char* name, const char* sourceFile)
    {
        (Registration<BaseT<Dims>, ModelT<Dims>>(name, sourceFile), ...);
    }
};

// The error for an unknown model name: sorted valid names, "did you mean", and the libs hint
// (not for a family that a case's libraries cannot extend, e.g. sphStudy's metrics).
InputError unknownModelError(const std::string& family, const std::string& name,
                             const SourceLocation& where, int dimension,
                             bool caseLibraries = true);

// Whether a case's `libs` can add models to the family (a family says no by declaring
// `static constexpr bool caseLibraries = false;`).
template <class Base>
constexpr bool extensibleByCase()
{
    if constexpr (requires { Base::caseLibraries; })
    {
        return Base::caseLibraries;
    }
    else
    {
        return true;
    }
}

// What a selector may add to the plain `type NAME;` selection.
struct Selection
{
    Selection(std::string type = {}, Schema keys = {}, std::vector<std::string> names = {})
        : defaultType(std::move(type)), extraKeys(std::move(keys)), bodies(std::move(names))
    {
    }
    // Only the case's bodies: selectModel<Contact<D>>(dict, args, D, Selection::withBodies(b)).
    static Selection withBodies(std::vector<std::string> names)
    {
        return {{}, {}, std::move(names)};
    }

    std::string defaultType; // used when `type` is absent (empty: `type` is required)
    Schema extraKeys;        // keys the caller reads from the same dictionary (e.g. `region`)
    std::vector<std::string> bodies; // the case's bodies, checked by Key::body (empty: unknown)
};

// Reads `type` from `dict`, finds the model, validates `dict` against its schema and builds it.
// `dimension` sizes vector keys (0 when the family is dimension-independent and vectors are
// not used).
template <class Base>
std::unique_ptr<Base> selectModel(const Dictionary& dict, const typename Base::Args& args,
                                  int dimension, const Selection& selection = {})
{
    const std::string family = Base::family;
    const Entry* type = dict.find("type");
    std::string name = selection.defaultType;
    SourceLocation where = dict.location();
    if (type && !type->isDict() && type->items().size() == 1 &&
        type->items()[0].kind() == Item::Kind::Word)
    {
        name = type->items()[0].text();
        where = type->items()[0].location();
    }
    else if (type || name.empty())
    {
        const auto names = RegistryStore::instance().names(family, Base::dimension);
        throw InputError(type ? type->valueLocation() : dict.location(),
                         (type ? "'type' in '" + dict.displayName() + "' must be one word"
                               : "missing required key 'type' in '" + dict.displayName() + "'"),
                         {"Valid " + family + " types (" + std::to_string(names.size()) +
                          "): " + joinSorted(names)});
    }
    const ModelRecord* record = Registry<Base>::find(name);
    if (!record)
    {
        throw unknownModelError(family, name, where, Base::dimension, extensibleByCase<Base>());
    }
    Schema schema = record->schema();
    schema.include(selection.extraKeys);
    ValidationContext context;
    context.dimension = dimension;
    context.label = name;
    context.bodies = selection.bodies;
    context.otherModelsWith = [family, name](const std::string& key)
    {
        std::vector<std::string> owners;
        for (const std::string& other : RegistryStore::instance().names(family, Base::dimension))
        {
            const ModelRecord* model = Registry<Base>::find(other);
            if (other != name && model && model->schema().find(key))
            {
                owners.push_back(other);
            }
        }
        return owners;
    };
    return Registry<Base>::create(name, schema.validate(dict, context), args);
}

// Validates `dict` against model `name` and builds it (for code and tests that know the name).
template <class Base>
std::unique_ptr<Base> createModel(const std::string& name, const Dictionary& dict,
                                  const typename Base::Args& args, int dimension)
{
    const ModelRecord* record = Registry<Base>::find(name);
    if (!record)
    {
        throw unknownModelError(Base::family, name, dict.location(), Base::dimension,
                                extensibleByCase<Base>());
    }
    return Registry<Base>::create(name, record->schema().validate(dict, name, dimension), args);
}

} // namespace sph

#define SPH_CONCAT_IMPL(a, b) a##b
#define SPH_CONCAT(a, b) SPH_CONCAT_IMPL(a, b)

#define SPH_REGISTER_MODEL(Base, Model, name)                                                      \
    static const ::sph::Registration<Base, Model> SPH_CONCAT(sphRegistration_, __LINE__)(name,     \
                                                                                         __FILE__)

#define SPH_REGISTER_DIM_MODEL(BaseT, ModelT, name)                                                \
    static const ::sph::DimRegistration<BaseT, ModelT, 1, 2, 3> SPH_CONCAT(sphRegistration_,       \
                                                                           __LINE__)(name, __FILE__)

#define SPH_REGISTER_DIM_MODEL_FOR(BaseT, ModelT, name, ...)                                       \
    static const ::sph::DimRegistration<BaseT, ModelT, __VA_ARGS__> SPH_CONCAT(                    \
        sphRegistration_, __LINE__)(name, __FILE__)
