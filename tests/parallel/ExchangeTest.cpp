// Particles between ranks (libraries/parallel/ParticleExchange): every stored field of the
// registry, and a ragged one (a variable number of entries per particle), migrates and is
// ghosted with the same bits, and the property the bit-identical distributed run rests on: on
// every rank, the neighbour list of each owned particle, read as global ids, is the serial
// run's list, term for term and in the same order.
#include "parallel/Communicator.hpp"
#include "parallel/ParticleExchange.hpp"
#include "parallel/RcbPartition.hpp"
#include "particles/NeighbourList.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sph;

namespace
{

constexpr int columns = 40;
constexpr int rows = 25;
constexpr int total = columns * rows;
constexpr double spacing = 0.01;
constexpr int firstOfBody1 = 13 * columns; // rows 0-12 are body 0, rows 13-24 body 1

// Particle g's values: a perturbed lattice (distances that are not all equal), values whose
// bits depend on g, and a body 1 that may have been moved away by `shift`.
Vec<2> positionOf(int g, double shift)
{
    Vec<2> x(spacing * (g % columns) + 1e-3 * std::sin(1.7 * g),
             spacing * (g / columns) + 1e-3 * std::cos(2.3 * g));
    if (g >= firstOfBody1)
    {
        x[0] += shift;
    }
    return x;
}
Mat<2> gradientOf(int g, double version)
{
    Mat<2> F;
    F << 1.0 + 1e-3 * g, std::sqrt(g + version), -std::exp(-1e-3 * g), version / 3.0;
    return F;
}

// Particle g's entries of a per-particle quantity of variable length: g % 5 entries (none
// for some), 2 numbers each.
std::vector<double> entriesOf(int g)
{
    std::vector<double> values;
    for (int e = 0; e < g % 5; ++e)
    {
        values.push_back(g + 0.25 * e);
        values.push_back(std::sqrt(g + 0.1 * e));
    }
    return values;
}

// A registry like the solver's: bound arrays of several kinds and C++ types.
struct LocalParticles
{
    ParticleFields<2> fields;
    std::vector<int> id;
    std::vector<Vec<2>> x;
    std::vector<int> body;
    std::vector<Mat<2>> F;
    std::vector<Tensor3<2>> G;
    std::vector<std::uint8_t> yielding;
    RaggedVectors entries{"entries", 2};

    LocalParticles()
    {
        fields.bindRagged(entries);
        fields.bind(FieldSpec::integer("globalId", "global id").restart(), id);
        fields.bind(FieldSpec::vector("position", "x").restart().display(), x);
        fields.bind(FieldSpec::integer("bodyId", "body").restart(), body);
        fields.bind(FieldSpec::tensor("F", "deformation gradient").restart(), F);
        fields.bind(FieldSpec::thirdOrderTensor("G", "its gradient").restart(), G);
        fields.bind(FieldSpec::integer("yielding", "flag"), yielding);
        fields.derive<double>(FieldSpec::scalar("J", "det F").display(),
                              [this](std::size_t a) { return F[a].determinant(); });
    }

    void add(int g, double shift)
    {
        id.push_back(g);
        x.push_back(positionOf(g, shift));
        body.push_back(g >= firstOfBody1 ? 1 : 0);
        F.push_back(gradientOf(g, 0.0));
        Tensor3<2> t = Tensor3<2>::zero();
        t(1, 0, 1) = 0.5 * g;
        G.push_back(t);
        yielding.push_back(static_cast<std::uint8_t>(g % 2));
        entries.values.push_back(entriesOf(g));
        fields.setSize(id.size());
    }
};

std::vector<std::uint64_t> idsOf(const std::vector<int>& id)
{
    return {id.begin(), id.end()};
}

// Every local particle (owned or ghost) holds its own particle's values, bit for bit.
void checkValues(const LocalParticles& p, double shift, double version)
{
    for (std::size_t a = 0; a < p.id.size(); ++a)
    {
        const int g = p.id[a];
        INFO("particle " << g);
        REQUIRE(p.x[a] == positionOf(g, shift));
        REQUIRE(p.body[a] == (g >= firstOfBody1 ? 1 : 0));
        REQUIRE(p.F[a] == gradientOf(g, version));
        REQUIRE(p.G[a](1, 0, 1) == 0.5 * g);
        REQUIRE(p.yielding[a] == g % 2);
        REQUIRE(p.entries.values[a] == entriesOf(g));
    }
    REQUIRE(p.entries.size() == p.id.size());
}

// The neighbour list of every owned particle, as global ids, equals the serial run's.
void checkNeighbourOrder(const LocalParticles& p, const ParticleExchange<2>& exchange, double shift,
                         double radius)
{
    std::vector<Vec<2>> allX;
    std::vector<int> allBody;
    for (int g = 0; g < total; ++g)
    {
        allX.push_back(positionOf(g, shift));
        allBody.push_back(g >= firstOfBody1 ? 1 : 0);
    }
    const NeighbourList serial = buildNeighbourList<2>(allX, allBody, radius);
    const NeighbourList local = buildNeighbourList<2>(p.x, p.body, radius);
    std::size_t compared = 0;
    for (std::size_t a = 0; a < p.id.size(); ++a)
    {
        if (!exchange.owned(a))
        {
            continue;
        }
        const auto g = static_cast<std::size_t>(p.id[a]);
        std::vector<int> expected, got;
        for (std::size_t k = serial.begin(g); k < serial.end(g); ++k)
        {
            expected.push_back(static_cast<int>(serial.indices[k]));
        }
        for (std::size_t k = local.begin(a); k < local.end(a); ++k)
        {
            got.push_back(p.id[local.indices[k]]);
        }
        INFO("particle " << g);
        REQUIRE(got == expected);
        ++compared;
    }
    CHECK(compared == exchange.ownedCount());
}

} // namespace

TEST_CASE("exchange: particles migrate and are ghosted with every stored field, in global id order",
          "[parallel]")
{
    const Communicator comm = Communicator::world();
    const int n = comm.size();
    ParticleExchange<2> exchange(comm);
    LocalParticles p;
    // Dealt round-robin: every particle but rank 0's share must move.
    for (int g = comm.rank(); g < total; g += n)
    {
        p.add(g, 0.0);
    }
    exchange.migrate(p.fields, p.id, rcbOwners<2>(comm, p.x, idsOf(p.id)));
    REQUIRE(p.fields.size() == p.id.size());
    CHECK(comm.sum(static_cast<long long>(p.id.size())) == total);
    CHECK(comm.sum(static_cast<double>(p.id.size())) == total); // owned once: no duplicates
    CHECK(std::is_sorted(p.id.begin(), p.id.end()));
    CHECK(std::adjacent_find(p.id.begin(), p.id.end()) == p.id.end());
    long long idSum = 0;
    for (const int g : p.id)
    {
        idSum += g;
    }
    CHECK(comm.sum(idSum) == static_cast<long long>(total) * (total - 1) / 2);
    checkValues(p, 0.0, 0.0);
    if (n > 1)
    {
        CHECK(exchange.bytesSent() > 0);
    }

    // Two layers of a 2.2-spacing support (a scheme that reads its neighbours' F and G).
    const double radius = 2.2 * spacing;
    exchange.addGhosts(p.fields, p.x, p.id, 2.0 * radius);
    CHECK(exchange.ownedCount() + exchange.ghostCount() == p.id.size());
    CHECK(comm.sum(static_cast<long long>(exchange.ownedCount())) == total);
    CHECK(std::adjacent_find(p.id.begin(), p.id.end(), std::greater_equal<>()) == p.id.end());
    if (n == 1)
    {
        CHECK(exchange.ghostCount() == 0);
    }
    else
    {
        CHECK(comm.minimum(static_cast<double>(exchange.ghostCount())) > 0.0);
    }
    checkValues(p, 0.0, 0.0);
    checkNeighbourOrder(p, exchange, 0.0, radius);

    SECTION("owners' new values reach the ghosts")
    {
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            if (exchange.owned(a))
            {
                p.F[a] = gradientOf(p.id[a], 1.0);
            }
        }
        exchange.updateGhosts(p.fields, {"F"});
        checkValues(p, 0.0, 1.0);
        CHECK_THROWS_AS(exchange.updateGhosts(p.fields, {"J"}), std::logic_error); // derived
        CHECK_THROWS_AS(exchange.updateGhosts(p.fields, {"nothing"}), std::logic_error);
    }

    SECTION("owners' values of an array outside the registry reach the ghosts")
    {
        std::vector<double> values(p.id.size());
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            values[a] = exchange.owned(a) ? 1.5 * p.id[a] : std::nan("");
        }
        exchange.updateGhostValues(values);
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            REQUIRE(values[a] == 1.5 * p.id[a]);
        }
        std::vector<double> wrongSize(p.id.size() + 1);
        CHECK_THROWS_AS(exchange.updateGhostValues(wrongSize), std::logic_error);
    }

    SECTION("a second reach, in other positions, adds the particles near there")
    {
        // As contact does: the reference positions' two radii, and a narrower reach in the
        // current positions, where body 1 has moved 0.3 m to the left over body 0.
        const auto currentOf = [](int g) {
            Vec<2> x = positionOf(g, 0.0);
            x[0] -= g >= firstOfBody1 ? 0.3 : 0.0;
            return x;
        };
        exchange.removeGhosts(p.fields);
        std::vector<Vec<2>> current(p.id.size());
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            current[a] = currentOf(p.id[a]);
        }
        const double reach = 1.1 * spacing;
        p.fields.bind(FieldSpec::vector("current", "x now").restart(), current);
        exchange.addGhosts(p.fields, {{&p.x, 2.0 * radius}, {&current, reach}}, p.id);
        CHECK(std::adjacent_find(p.id.begin(), p.id.end(), std::greater_equal<>()) == p.id.end());
        checkValues(p, 0.0, 0.0);
        checkNeighbourOrder(p, exchange, 0.0, radius);
        // Every particle within `reach` of an owned one in the current positions is local.
        std::vector<Vec<2>> allCurrent;
        for (int g = 0; g < total; ++g)
        {
            allCurrent.push_back(currentOf(g));
        }
        std::size_t checked = 0;
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            REQUIRE(current[a] == allCurrent[static_cast<std::size_t>(p.id[a])]);
            if (!exchange.owned(a))
            {
                continue;
            }
            for (int g = 0; g < total; ++g)
            {
                if ((allCurrent[static_cast<std::size_t>(g)] - current[a]).norm() <= reach)
                {
                    INFO("particle " << g << " near owned particle " << p.id[a]);
                    REQUIRE(std::binary_search(p.id.begin(), p.id.end(), g));
                    ++checked;
                }
            }
        }
        CHECK(comm.sum(static_cast<long long>(checked)) > total);
        const std::vector<Vec<2>> tooMany(total + 1, Vec<2>::Zero()); // one per particle, or misuse
        CHECK_THROWS_AS(exchange.addGhosts(p.fields, {{&tooMany, reach}}, p.id), std::logic_error);
    }

    SECTION("a body moved across the partition migrates, and the order holds again")
    {
        // Body 1 jumps by 0.25 m to the right: a third of the domain's width.
        const double shift = 0.25;
        for (std::size_t a = 0; a < p.id.size(); ++a)
        {
            p.x[a] = positionOf(p.id[a], shift);
        }
        exchange.removeGhosts(p.fields);
        CHECK(p.id.size() == exchange.ownedCount());
        CHECK(exchange.ghostCount() == 0);
        const std::vector<int> owners = rcbOwners<2>(comm, p.x, idsOf(p.id));
        long long leaving = 0;
        for (const int o : owners)
        {
            leaving += o != comm.rank() ? 1 : 0;
        }
        if (n > 1)
        {
            CHECK(comm.sum(leaving) > 0);
        }
        exchange.migrate(p.fields, p.id, owners);
        CHECK(comm.sum(static_cast<long long>(p.id.size())) == total);
        exchange.addGhosts(p.fields, p.x, p.id, 2.0 * radius);
        checkValues(p, shift, 0.0);
        checkNeighbourOrder(p, exchange, shift, radius);
    }
}

TEST_CASE("exchange: misuse is a programming error, not a wrong result", "[parallel]")
{
    const Communicator comm = Communicator::world();
    ParticleExchange<2> exchange(comm);
    LocalParticles p;
    p.add(comm.rank(), 0.0);
    CHECK_THROWS_AS(exchange.migrate(p.fields, p.id, {comm.size()}), std::logic_error);
    CHECK_THROWS_AS(exchange.migrate(p.fields, p.id, {}), std::logic_error);
}
