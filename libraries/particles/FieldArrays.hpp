#pragma once
// How the field registry (particles/ParticleFields.hpp) sees one field: as numbers. A value's
// "native" components (D for a vector, D×D row-major for a tensor, D×D×D with the last index
// fastest for a third-order tensor) to and from its C++ type, and the FieldArray adapters:
// a stored std::vector, a derived display quantity, a derived quantity served in pieces.

#include "core/FieldSpec.hpp"
#include "particles/Types.hpp"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sph
{

// Native component count of a kind in dimension D.
template <int D>
constexpr int nativeComponents(FieldKind kind)
{
    switch (kind)
    {
    case FieldKind::integer:
    case FieldKind::scalar: return 1;
    case FieldKind::vector: return D;
    case FieldKind::tensor: return D * D;
    case FieldKind::thirdOrderTensor: return D * D * D;
    }
    return 0;
}

namespace fieldValues
{
// One value to and from its native components. (In 1D, Vec<1> and Mat<1> are the same type;
// both have one component, so one overload serves both.)
inline void get(int value, double* out) { out[0] = value; }
inline void set(const double* in, int& value) { value = static_cast<int>(in[0]); }
inline void get(std::uint8_t value, double* out) { out[0] = value; }
inline void set(const double* in, std::uint8_t& value) { value = static_cast<std::uint8_t>(in[0]); }
inline void get(double value, double* out) { out[0] = value; }
inline void set(const double* in, double& value) { value = in[0]; }

template <int R, int C>
void get(const Eigen::Matrix<double, R, C>& value, double* out)
{
    for (int i = 0; i < R; ++i)
    {
        for (int j = 0; j < C; ++j)
        {
            out[i * C + j] = value(i, j);
        }
    }
}
template <int R, int C>
void set(const double* in, Eigen::Matrix<double, R, C>& value)
{
    for (int i = 0; i < R; ++i)
    {
        for (int j = 0; j < C; ++j)
        {
            value(i, j) = in[i * C + j];
        }
    }
}

template <int D>
void get(const Tensor3<D>& value, double* out)
{
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            for (int k = 0; k < D; ++k)
            {
                out[D * D * i + D * j + k] = value(i, j, k);
            }
        }
    }
}
template <int D>
void set(const double* in, Tensor3<D>& value)
{
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            for (int k = 0; k < D; ++k)
            {
                value(i, j, k) = in[D * D * i + D * j + k];
            }
        }
    }
}

// The kind a C++ value type is stored as.
template <int D, class T>
constexpr bool matchesKind(FieldKind kind)
{
    if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::uint8_t>)
    {
        return kind == FieldKind::integer;
    }
    else if constexpr (std::is_same_v<T, double>)
    {
        return kind == FieldKind::scalar;
    }
    else if constexpr (std::is_same_v<T, Vec<D>> && std::is_same_v<T, Mat<D>>) // 1D
    {
        return kind == FieldKind::vector || kind == FieldKind::tensor;
    }
    else if constexpr (std::is_same_v<T, Vec<D>>)
    {
        return kind == FieldKind::vector;
    }
    else if constexpr (std::is_same_v<T, Mat<D>>)
    {
        return kind == FieldKind::tensor;
    }
    else if constexpr (std::is_same_v<T, Tensor3<D>>)
    {
        return kind == FieldKind::thirdOrderTensor;
    }
    else
    {
        return false;
    }
}
} // namespace fieldValues

// One field's values seen as numbers, whatever their C++ type.
class FieldArray
{
public:
    virtual ~FieldArray() = default;
    virtual std::size_t size() const = 0;
    // The native components of particle a's value into out[0 .. components).
    virtual void get(std::size_t a, double* out) const = 0;
    // Stored fields only: sets particle a's value from its native components.
    virtual void set(std::size_t a, const double* in) = 0;
    virtual void resize(std::size_t n) = 0;
    virtual bool stored() const = 0;
};

template <class T>
class StoredArray final : public FieldArray
{
public:
    explicit StoredArray(std::vector<T>& values, T fill) : values_(values), fill_(std::move(fill)) {}
    std::size_t size() const override { return values_.size(); }
    void get(std::size_t a, double* out) const override { fieldValues::get(values_[a], out); }
    void set(std::size_t a, const double* in) override { fieldValues::set(in, values_[a]); }
    void resize(std::size_t n) override { values_.resize(n, fill_); }
    bool stored() const override { return true; }

private:
    std::vector<T>& values_;
    T fill_;
};

template <class T>
class DerivedArray final : public FieldArray
{
public:
    DerivedArray(std::function<std::size_t()> size, std::function<T(std::size_t)> value)
        : size_(std::move(size)), value_(std::move(value))
    {
    }
    std::size_t size() const override { return size_(); }
    void get(std::size_t a, double* out) const override { fieldValues::get(value_(a), out); }
    void set(std::size_t, const double*) override
    {
        throw std::logic_error("a derived field cannot be set");
    }
    void resize(std::size_t) override {}
    bool stored() const override { return false; }

private:
    std::function<std::size_t()> size_;
    std::function<T(std::size_t)> value_;
};

// A display quantity computed piece by piece: each piece serves a range of particles (the body
// of one model instance); particles no piece covers show the fill value.
template <class T>
class PiecewiseDerivedArray final : public FieldArray
{
public:
    PiecewiseDerivedArray(std::function<std::size_t()> size, T fill)
        : size_(std::move(size)), fill_(std::move(fill))
    {
    }
    void addPiece(std::size_t begin, std::size_t end, std::function<T(std::size_t)> value)
    {
        pieces_.push_back({begin, end, std::move(value)});
    }
    std::size_t size() const override { return size_(); }
    void get(std::size_t a, double* out) const override
    {
        for (const Piece& piece : pieces_)
        {
            if (a >= piece.begin && a < piece.end)
            {
                fieldValues::get(piece.value(a), out);
                return;
            }
        }
        fieldValues::get(fill_, out);
    }
    void set(std::size_t, const double*) override
    {
        throw std::logic_error("a derived field cannot be set");
    }
    void resize(std::size_t) override {}
    bool stored() const override { return false; }

private:
    struct Piece
    {
        std::size_t begin;
        std::size_t end;
        std::function<T(std::size_t)> value;
    };
    std::function<std::size_t()> size_;
    T fill_;
    std::vector<Piece> pieces_;
};

} // namespace sph
