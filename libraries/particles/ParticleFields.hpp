#pragma once
// The per-particle field registry: every per-particle quantity of a run, each declared once
// (core/FieldSpec.hpp) with its storage. Whatever handles "all the particle data" iterates over
// it instead of naming arrays: VTK output and restart (solver/StateFile.hpp); later the ghost
// exchange and the migration of particles between ranks.
//
//   fields.bind(FieldSpec::vector("velocity", "v^n [m/s]").display(), velocitySync);
//   auto& peak = fields.declare<double>(peakSpeedField());       // a model's own array
//   fields.derive<double>(jSpec, [&](std::size_t a) { return F[a].determinant(); });
//
// Stored fields are either bound (the array is owned by whoever computes it: the particle set,
// the reference configuration, the time loop; the hot loops keep their plain std::vectors) or
// owned here (a model's history variables). Derived fields are display quantities computed
// from the others when written. Every field is seen through FieldArray as numbers: the
// "native" components of one value (D for a vector, D×D row-major for a tensor, D×D×D with the
// last index fastest for a third-order tensor).

#include "core/FieldSpec.hpp"
#include "particles/FieldArrays.hpp"
#include "particles/RaggedArray.hpp"
#include "particles/Types.hpp"

#include <deque>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sph
{

template <int D>
class ParticleFields
{
public:
    struct Field
    {
        FieldSpec spec;
        std::unique_ptr<FieldArray> array;
        int components() const { return nativeComponents<D>(spec.kind()); }
    };

    ParticleFields() = default;
    ParticleFields(const ParticleFields&) = delete; // derived fields refer to this registry
    ParticleFields& operator=(const ParticleFields&) = delete;

    // The array owned elsewhere; `fill` is the value of particles added by resize().
    template <class T>
    void bind(const FieldSpec& spec, std::vector<T>& values, std::type_identity_t<T> fill = zero<T>())
    {
        checkKind<T>(spec);
        add(spec, std::make_unique<StoredArray<T>>(values, std::move(fill)));
    }

    // An array owned here, sized to the particles (size()) and filled with `fill`. Declaring
    // the same spec again returns the same array (one model serving several bodies).
    template <class T>
    std::vector<T>& declare(const FieldSpec& spec, std::type_identity_t<T> fill = zero<T>())
    {
        checkKind<T>(spec);
        for (auto& owned : owned_)
        {
            if (owned.spec == spec)
            {
                return *static_cast<std::vector<T>*>(owned.values.get());
            }
        }
        auto values = std::make_shared<std::vector<T>>(size_, fill);
        std::vector<T>& result = *values;
        add(spec, std::make_unique<StoredArray<T>>(result, std::move(fill)));
        owned_.push_back({spec, std::shared_ptr<void>(values, values.get())});
        return result;
    }

    // A field seen through an array of one's own (e.g. one whose written values come from
    // elsewhere than where a restart puts them back).
    void bindArray(const FieldSpec& spec, std::unique_ptr<FieldArray> array)
    {
        add(spec, std::move(array));
    }

    // A display quantity computed from stored fields when it is written.
    template <class T>
    void derive(const FieldSpec& spec, std::type_identity_t<std::function<T(std::size_t)>> value)
    {
        checkKind<T>(spec);
        if (!spec.isDisplay() || spec.isRestart())
        {
            throw std::logic_error("derived field '" + spec.name() + "' must be display only");
        }
        add(spec, std::make_unique<DerivedArray<T>>([this] { return size_; }, std::move(value)));
    }

    // A display quantity of the particles [begin, end) served by one model instance; several
    // instances (one per body) add their pieces under the same spec, the others show zero.
    template <class T>
    void deriveOver(const FieldSpec& spec, std::size_t begin, std::size_t end,
                    std::type_identity_t<std::function<T(std::size_t)>> value)
    {
        checkKind<T>(spec);
        if (!spec.isDisplay() || spec.isRestart())
        {
            throw std::logic_error("derived field '" + spec.name() + "' must be display only");
        }
        for (auto& field : fields_)
        {
            if (field.spec == spec)
            {
                auto* pieces = dynamic_cast<PiecewiseDerivedArray<T>*>(field.array.get());
                if (!pieces)
                {
                    throw std::logic_error("particle field '" + spec.name() + "' is declared twice");
                }
                pieces->addPiece(begin, end, std::move(value));
                return;
            }
        }
        auto array = std::make_unique<PiecewiseDerivedArray<T>>([this] { return size_; }, zero<T>());
        array->addPiece(begin, end, std::move(value));
        add(spec, std::move(array));
    }

    // A per-particle quantity of variable length (particles/RaggedArray.hpp), owned by the
    // caller: it travels and is restart data like a stored field, but is never displayed.
    void bindRagged(RaggedArray& array)
    {
        for (const RaggedArray* other : ragged_)
        {
            if (other->name() == array.name())
            {
                throw std::logic_error("ragged particle field '" + array.name() + "' is declared twice");
            }
        }
        ragged_.push_back(&array);
    }
    const std::vector<RaggedArray*>& ragged() const { return ragged_; }

    // Sets the particle count of every stored field (new particles get each field's fill, and
    // no entries of a ragged one).
    void resize(std::size_t n)
    {
        size_ = n;
        for (auto& field : fields_)
        {
            field.array->resize(n);
        }
        for (RaggedArray* array : ragged_)
        {
            array->resize(n);
        }
    }
    // The particle count declare() sizes new arrays to.
    void setSize(std::size_t n) { size_ = n; }
    std::size_t size() const { return size_; }

    const std::deque<Field>& all() const { return fields_; }
    std::deque<Field>& all() { return fields_; }
    const Field* find(const std::string& name) const
    {
        for (const auto& field : fields_)
        {
            if (field.spec.name() == name)
            {
                return &field;
            }
        }
        return nullptr;
    }

private:
    template <class T>
    static T zero()
    {
        if constexpr (std::is_arithmetic_v<T>)
        {
            return T{};
        }
        else if constexpr (std::is_same_v<T, Tensor3<D>>)
        {
            return Tensor3<D>::zero();
        }
        else
        {
            return T::Zero();
        }
    }

    template <class T>
    static void checkKind(const FieldSpec& spec)
    {
        if (!fieldValues::matchesKind<D, T>(spec.kind()))
        {
            throw std::logic_error("field '" + spec.name() + "' is declared " +
                                   toString(spec.kind()) + " but stored as another type");
        }
    }

    void add(const FieldSpec& spec, std::unique_ptr<FieldArray> array)
    {
        for (const auto& field : fields_)
        {
            if (field.spec.name() == spec.name() || field.spec.fileName() == spec.fileName())
            {
                throw std::logic_error("particle field '" + spec.name() + "' is declared twice");
            }
        }
        fields_.push_back({spec, std::move(array)});
    }

    struct Owned
    {
        FieldSpec spec;
        std::shared_ptr<void> values;
    };

    std::size_t size_ = 0;
    std::deque<Field> fields_;
    std::vector<Owned> owned_;
    std::vector<RaggedArray*> ragged_;
};

} // namespace sph
