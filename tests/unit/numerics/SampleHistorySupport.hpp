#pragma once
// A body's gradF samples and their SampleHistory, for the tests of the store
// (SampleHistoryTest.cpp, SampleRowsTest.cpp): a lattice with j2Plasticity, its neighbour list,
// random plastic states and one evaluation's pending states.
#include "materials/plasticity/PlasticHistory.hpp"
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/gradF/SampleHistory.hpp"

#include <algorithm>
#include <cstring>
#include <random>

namespace sph::test::samples
{

inline const char* kJ2 = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 0.5; hardeningModulus 0.2;";

inline bool sameBits(const double* x, const double* y, std::size_t n)
{
    return std::memcmp(x, y, n * sizeof(double)) == 0;
}

// A packed plastic state with a random symmetric Cp⁻¹ and α > 0.
template <int D>
std::vector<double> randomState(std::mt19937& random)
{
    std::uniform_real_distribution<double> uniform(-0.2, 0.2);
    PlasticState<D> s;
    for (int i = 0; i < D; ++i)
    {
        for (int j = i; j < D; ++j)
        {
            s.inversePlastic(i, j) = (i == j ? 1.0 : 0.0) + uniform(random);
            s.inversePlastic(j, i) = s.inversePlastic(i, j);
        }
    }
    s.inversePlasticZZ = 1.0 + uniform(random);
    s.alpha = 0.3 + uniform(random);
    std::vector<double> packed(PlasticState<D>::packedSize);
    s.pack(packed.data());
    return packed;
}

// A body of lattice points with j2Plasticity and its neighbour list; the samples laid out
// along it, or (perParticle > 0) that many a particle (gradF's moment points, §M7).
template <int D>
struct Samples
{
    ParticleFields<D> fields;
    std::unique_ptr<Material<D>> material;
    std::vector<const Material<D>*> materials;
    std::vector<int> body;
    std::vector<Vec<D>> x;
    NeighbourList list;
    SampleHistory<D> history;
    std::size_t stride = 0;

    explicit Samples(unsigned seed, std::size_t perParticle = 0)
    {
        x = test::lattice<D>(D == 3 ? 4 : 6, 0.2, seed);
        body.assign(x.size(), 0);
        fields.setSize(x.size());
        material = test::build<Material<D>>(kJ2, {&fields, BodyRange{"body", 0, x.size()}, nullptr}, D);
        materials = {material.get()};
        history.declare(materials, fields, false, perParticle);
        stride = history.stride();
        relist(x);
    }
    void relist(const std::vector<Vec<D>>& at, double radius = 1.6)
    {
        list = buildNeighbourList<D>(at, body, radius);
        history.listChanged();
        history.follow(list, body, materials, nullptr);
    }
    // Particle a's samples: its neighbours', or perParticle.
    std::size_t count(std::size_t a) const
    {
        return history.perParticle() > 0 ? history.perParticle() : list.count(a);
    }
    std::vector<double> read(std::size_t a) const
    {
        std::vector<double> states(count(a) * stride);
        history.read(history.begin(a), count(a), states.data());
        return states;
    }
    std::vector<double> initial() const
    {
        std::vector<double> state(stride);
        PlasticState<D>{}.pack(state.data());
        return state;
    }
};

// Packed states (read()'s layout) in rows of rowLength (readRows()'s), the entries past the
// last state `pad`.
inline std::vector<double> inRows(const std::vector<double>& packed, std::size_t stride,
                                  std::size_t rowLength, const std::vector<double>& pad)
{
    const std::size_t count = packed.size() / stride;
    std::vector<double> rows(rowLength * stride);
    for (std::size_t c = 0; c < stride; ++c)
    {
        for (std::size_t j = 0; j < rowLength; ++j)
        {
            rows[c * rowLength + j] = j < count ? packed[j * stride + c] : pad[c];
        }
    }
    return rows;
}

// One evaluation's `next` states: every third sample (shifted by round) gets a new state, the
// rest are the committed ones copied, as ReturnMapPlasticity::evaluate writes them.
template <int D>
std::vector<std::vector<double>> evaluate(Samples<D>& s, int round, std::mt19937& random)
{
    s.history.clearPending();
    std::vector<std::vector<double>> next(s.x.size());
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        next[a] = s.read(a);
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            if ((j + static_cast<std::size_t>(round)) % 3 == 0)
            {
                const std::vector<double> state = randomState<D>(random);
                std::copy(state.begin(), state.end(), &next[a][j * s.stride]);
            }
        }
        s.history.keepPending(s.list.begin(a), s.list.count(a), next[a].data());
    }
    return next;
}

template <int D>
std::size_t countNotInitial(const Samples<D>& s)
{
    const std::vector<double> initial = s.initial();
    std::size_t count = 0;
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        const std::vector<double> states = s.read(a);
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            count += sameBits(&states[j * s.stride], initial.data(), s.stride) ? 0 : 1;
        }
    }
    return count;
}

} // namespace sph::test::samples
