// The region models: each is a few lines, registered here in one line each.
#include "particles/regions/Region.hpp"

#include <limits>

namespace sph
{

// all: every particle of the body.
template <int D>
class AllRegion : public Region<D>
{
public:
    static std::string description() { return "Every particle of the body."; }
    static Schema schema() { return Schema(); }
    AllRegion(const Params&, const typename Region<D>::Args&) {}

protected:
    bool contains(const Vec<D>&) const override { return true; }
};

// box: min <= X <= max componentwise.
template <int D>
class BoxRegion : public Region<D>
{
public:
    static std::string description() { return "Axis-aligned box: min <= X <= max."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("min", "lower corner [m]"))
            .add(Key::vector("max", "upper corner [m]"));
    }
    BoxRegion(const Params& p, const typename Region<D>::Args&)
        : min_(toVec<D>(p.vector("min"))), max_(toVec<D>(p.vector("max")))
    {
        if ((max_.array() < min_.array()).any())
        {
            p.fail("max", "box: 'max' must not be below 'min' in any component");
        }
    }

protected:
    bool contains(const Vec<D>& point) const override
    {
        return (point.array() >= min_.array()).all() && (point.array() <= max_.array()).all();
    }

private:
    Vec<D> min_;
    Vec<D> max_;
};

// sphere: |X - centre| <= radius (an interval in 1D, a disk in 2D).
template <int D>
class SphereRegion : public Region<D>
{
public:
    static std::string description() { return "Ball |X - centre| <= radius."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("centre", "centre [m]"))
            .add(Key::real("radius", "radius [m]").positive());
    }
    SphereRegion(const Params& p, const typename Region<D>::Args&)
        : centre_(toVec<D>(p.vector("centre"))), radius_(p.real("radius"))
    {
    }

protected:
    bool contains(const Vec<D>& point) const override
    {
        return (point - centre_).norm() <= radius_;
    }

private:
    Vec<D> centre_;
    double radius_;
};

// halfSpace: (X - point)·normal >= 0.
template <int D>
class HalfSpaceRegion : public Region<D>
{
public:
    static std::string description() { return "Half space (X - point).normal >= 0."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("point", "a point on the boundary plane [m]"))
            .add(Key::vector("normal", "direction into the region"));
    }
    HalfSpaceRegion(const Params& p, const typename Region<D>::Args&)
        : point_(toVec<D>(p.vector("point"))), normal_(toVec<D>(p.vector("normal")))
    {
        if (normal_.norm() == 0.0)
        {
            p.fail("normal", "halfSpace: 'normal' must not be the zero vector");
        }
    }

protected:
    bool contains(const Vec<D>& X) const override { return (X - point_).dot(normal_) >= 0.0; }

private:
    Vec<D> point_;
    Vec<D> normal_;
};

// nearest: the single particle whose X is closest to `point` (lowest index on ties).
template <int D>
class NearestRegion : public Region<D>
{
public:
    static std::string description()
    {
        return "The one particle of the body closest to 'point' (e.g. a bar's end).";
    }
    static Schema schema() { return Schema().add(Key::vector("point", "target point [m]")); }
    NearestRegion(const Params& p, const typename Region<D>::Args&)
        : point_(toVec<D>(p.vector("point")))
    {
    }
    std::vector<std::size_t> select(const std::vector<Vec<D>>& X, std::size_t begin,
                                    std::size_t end) const override
    {
        std::size_t best = begin;
        double bestDistance = std::numeric_limits<double>::max();
        for (std::size_t i = begin; i < end; ++i)
        {
            const double distance = (X[i] - point_).squaredNorm();
            if (distance < bestDistance)
            {
                best = i;
                bestDistance = distance;
            }
        }
        return begin < end ? std::vector<std::size_t>{best} : std::vector<std::size_t>{};
    }

protected:
    bool contains(const Vec<D>&) const override { return false; }

private:
    Vec<D> point_;
};

SPH_REGISTER_DIM_MODEL(Region, AllRegion, "all");
SPH_REGISTER_DIM_MODEL(Region, BoxRegion, "box");
SPH_REGISTER_DIM_MODEL(Region, SphereRegion, "sphere");
SPH_REGISTER_DIM_MODEL(Region, HalfSpaceRegion, "halfSpace");
SPH_REGISTER_DIM_MODEL(Region, NearestRegion, "nearest");

} // namespace sph
