// The storage of gradF's per-sample history (SampleHistory, issue 30), against the dense
// layout it replaced (a committed and a next state per pair, the commit a copy):
//   - a sample in the initial state keeps no record and reads as that state;
//   - the commit, in place and of the states that changed only, leaves the states the copy of
//     the last evaluation's left (an earlier evaluation's are dropped);
//   - when the list changes, a kept pair keeps its state, a new one starts from its owner's,
//     and the records of the pairs that left are reused;
//   - the restart field (get/assign) round-trips bit for bit, in the full packed layout;
//   - a plastic state's compact form (Cp⁻¹'s upper triangle) unpacks bit for bit, and a state
//     whose Cp⁻¹ is not symmetric bit for bit is refused, not rounded;
//   - keepPending() keeps a sample the material flags as changed without comparing it where it
//     has a record (the commit rewrites the same numbers), and none where it is in the initial
//     state;
//   - StatePool's records keep their address and contents as it grows, released ones are reused,
//     releaseAll() hands them out again in the same memory, and relocate() puts them in a given
//     order in place (follow() does, once they scatter).
#include "numerics/SampleHistorySupport.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <random>

using namespace sph;

namespace
{

using namespace test::samples;

template <int D>
void initialSamplesKeepNoRecord()
{
    INFO(D << "D");
    Samples<D> s(3);
    REQUIRE(s.list.pairCount() > 5 * s.x.size());
    CHECK(s.history.storedStates() == 0);
    const std::vector<double> initial = s.initial();
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        const std::vector<double> states = s.read(a);
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            REQUIRE(sameBits(&states[j * s.stride], initial.data(), s.stride));
        }
        // The restart entry: [neighbour, state] each.
        std::vector<double> entries(s.history.entries(a) * s.history.width());
        s.history.get(a, entries.data());
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            CHECK(entries[j * s.history.width()] == static_cast<double>(s.list.indices[s.list.begin(a) + j]));
            CHECK(sameBits(&entries[j * s.history.width() + 1], initial.data(), s.stride));
        }
    }
}

template <int D>
void commitInPlaceIsTheCopy()
{
    INFO(D << "D");
    Samples<D> s(5);
    std::mt19937 random(11);
    for (int round = 0; round < 3; ++round)
    {
        // An earlier evaluation's states are not committed: only the last one's.
        evaluate<D>(s, round + 1, random);
        const std::vector<std::vector<double>> next = evaluate<D>(s, round, random);
        std::vector<std::vector<double>> before(s.x.size());
        for (std::size_t a = 0; a < s.x.size(); ++a)
        {
            before[a] = s.read(a);
        }
        // Pending states are not the committed ones until the commit.
        for (std::size_t a = 0; a < s.x.size(); ++a)
        {
            REQUIRE(s.read(a) == before[a]);
        }
        s.history.commit();
        for (std::size_t a = 0; a < s.x.size(); ++a)
        {
            const std::vector<double> after = s.read(a);
            REQUIRE(sameBits(after.data(), next[a].data(), after.size()));
        }
        CHECK(s.history.storedStates() == countNotInitial(s));
        // A third of the samples flowed for the first time: the commit relocated the records,
        // new ones included, into slot order (a total-Lagrangian list is never follow()ed).
        CHECK(s.history.recordsInSlotOrder());
        if (round == 0)
        {
            CHECK(s.history.storedStates() < s.list.pairCount() / 2); // a third of them changed
        }
    }
    // A commit without a new evaluation changes nothing (what was pending was committed).
    std::vector<std::vector<double>> committed(s.x.size());
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        committed[a] = s.read(a);
    }
    s.history.commit();
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        CHECK(s.read(a) == committed[a]);
    }
}

template <int D>
void followKeepsAndStartsStates()
{
    INFO(D << "D");
    Samples<D> s(7);
    std::mt19937 random(13);
    evaluate<D>(s, 0, random);
    s.history.commit();
    // Particle 1's own state is not the initial one: its new pairs start from it.
    REQUIRE(s.material->startFromStress(1, 0.01 * Eigen::Matrix3d::Identity()) ==
            Material<D>::InitialStress::set);
    std::vector<double> owner1(s.stride);
    s.material->packHistory(1, owner1.data());
    REQUIRE(!sameBits(owner1.data(), s.initial().data(), s.stride));
    std::vector<std::map<std::size_t, std::vector<double>>> old(s.x.size());
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        const std::vector<double> states = s.read(a);
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            old[a][s.list.indices[s.list.begin(a) + j]] =
                std::vector<double>(&states[j * s.stride], &states[(j + 1) * s.stride]);
        }
    }
    std::vector<Vec<D>> moved = s.x;
    std::mt19937 jitter(17);
    std::uniform_real_distribution<double> uniform(-0.3, 0.3);
    for (Vec<D>& p : moved)
    {
        for (int d = 0; d < D; ++d)
        {
            p[d] += uniform(jitter);
        }
    }
    s.relist(moved);
    std::size_t kept = 0;
    std::size_t added = 0;
    // Both kinds of particle: those whose neighbours did not change (follow() keeps their
    // slots by copies) and those whose list changed (the merge by global index).
    std::size_t sameList = 0;
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        bool same = s.list.count(a) == old[a].size();
        for (std::size_t j = 0; same && j < s.list.count(a); ++j)
        {
            same = old[a].count(s.list.indices[s.list.begin(a) + j]) == 1;
        }
        sameList += same ? 1 : 0;
        std::vector<double> own(s.stride);
        s.material->packHistory(a, own.data());
        const std::vector<double> states = s.read(a);
        for (std::size_t j = 0; j < s.list.count(a); ++j)
        {
            const auto found = old[a].find(s.list.indices[s.list.begin(a) + j]);
            const double* state = &states[j * s.stride];
            if (found != old[a].end())
            {
                ++kept;
                REQUIRE(sameBits(state, found->second.data(), s.stride));
            }
            else
            {
                ++added;
                REQUIRE(sameBits(state, own.data(), s.stride));
            }
        }
    }
    CHECK(kept > 0);
    CHECK(added > 0);
    CHECK(sameList > 0);
    CHECK(sameList < s.x.size());
    // The records of the pairs that left were released (and reused).
    CHECK(s.history.storedStates() == countNotInitial(s));
}

template <int D>
void restartFieldRoundTrips()
{
    INFO(D << "D");
    Samples<D> s(9);
    std::mt19937 random(19);
    evaluate<D>(s, 1, random);
    s.history.commit();
    std::vector<std::size_t> counts(s.x.size());
    std::vector<double> values;
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        counts[a] = s.history.entries(a);
        values.resize(values.size() + counts[a] * s.history.width());
        s.history.get(a, values.data() + values.size() - counts[a] * s.history.width());
    }
    CHECK(s.history.width() == 1 + PlasticState<D>::packedSize);
    Samples<D> t(9);
    t.history.assign(counts, values);
    CHECK(t.history.storedStates() == s.history.storedStates());
    std::vector<double> again(values.size());
    std::size_t at = 0;
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        t.history.get(a, again.data() + at);
        at += counts[a] * t.history.width();
    }
    CHECK(sameBits(again.data(), values.data(), values.size()));
    // Laid out along the same list again, the states are where they were.
    t.history.follow(s.list, s.body, t.materials, nullptr);
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        REQUIRE(t.read(a) == s.read(a));
    }
    // A state whose Cp⁻¹ is not symmetric bit for bit cannot be kept exactly: refused.
    values[1 + 1] = std::nextafter(values[1 + D], 2.0);
    CHECK_THROWS_WITH(t.history.assign(counts, values), Catch::Contains("not symmetric"));
}

template <int D>
void compactFormIsExact()
{
    INFO(D << "D");
    // j2Plasticity keeps no flow pressure, druckerPrager does (one number more).
    CHECK(PlasticState<D>::compactSize(false) == D * (D + 1) / 2 + (D == 2 ? 1 : 0) + 1);
    CHECK(PlasticState<D>::compactSize(true) == PlasticState<D>::compactSize(false) + 1);
    std::mt19937 random(23);
    std::uniform_real_distribution<double> pressure(-1e4, 1e3);
    for (const bool withFlowPressure : {false, true})
    {
        INFO("with the flow pressure: " << withFlowPressure);
        std::vector<double> compact(PlasticState<D>::compactSize(withFlowPressure));
        std::vector<double> back(PlasticState<D>::packedSize);
        for (int i = 0; i < 100; ++i)
        {
            std::vector<double> state = randomState<D>(random);
            if (withFlowPressure && i % 2 == 1)
            {
                state[PlasticState<D>::flowPressureAt] = pressure(random);
            }
            REQUIRE(PlasticState<D>::compact(state.data(), compact.data(), withFlowPressure));
            PlasticState<D>::expand(compact.data(), back.data(), withFlowPressure);
            REQUIRE(sameBits(back.data(), state.data(), state.size()));
        }
        if constexpr (D > 1)
        {
            std::vector<double> state = randomState<D>(random);
            state[1] = -0.0; // Cp⁻¹_01
            state[D] = 0.0;  // Cp⁻¹_10: equal, not the same bits
            CHECK_FALSE(PlasticState<D>::compact(state.data(), compact.data(), withFlowPressure));
        }
    }
    // A flow pressure the form without it cannot keep: refused, not dropped.
    std::vector<double> state = randomState<D>(random);
    state[PlasticState<D>::flowPressureAt] = -250.0;
    std::vector<double> compact(PlasticState<D>::compactSize(false));
    CHECK_FALSE(PlasticState<D>::compact(state.data(), compact.data(), false));
}

// keepPending() with the material's flags (ReturnMapPlasticity: changed = it flowed, or its
// flow pressure changed): a flagged sample with a record is kept without comparing it, so a
// commit of the states it already holds leaves them as they were; a flagged sample in the
// initial state still keeps no record; a state it cannot keep exactly stops, with or without
// the flags (the compaction by copies checks what the codec's compactHistory() does).
template <int D>
void changedFlagsKeepWithoutComparing()
{
    INFO(D << "D");
    Samples<D> s(7);
    std::mt19937 random(5);
    evaluate<D>(s, 0, random);
    s.history.commit();
    const std::size_t stored = s.history.storedStates();
    REQUIRE(stored > 0);
    REQUIRE(stored < s.list.pairCount());
    std::vector<std::vector<double>> before(s.x.size());
    s.history.clearPending();
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        before[a] = s.read(a);
        const std::vector<std::uint8_t> changed(s.list.count(a), 1);
        s.history.keepPending(s.list.begin(a), s.list.count(a), before[a].data(), changed.data());
    }
    s.history.commit();
    CHECK(s.history.storedStates() == stored);
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        const std::vector<double> after = s.read(a);
        REQUIRE(sameBits(after.data(), before[a].data(), after.size()));
    }
    if constexpr (D > 1)
    {
        std::vector<double> next = s.read(0);
        next[1] = std::nextafter(next[D], 2.0); // Cp⁻¹_01 ≠ Cp⁻¹_10 by one bit
        const std::vector<std::uint8_t> changed(s.list.count(0), 1);
        s.history.clearPending();
        CHECK_THROWS_WITH(s.history.keepPending(s.list.begin(0), s.list.count(0), next.data(),
                                                changed.data()),
                          Catch::Contains("not symmetric"));
        CHECK_THROWS_WITH(s.history.keepPending(s.list.begin(0), s.list.count(0), next.data()),
                          Catch::Contains("not symmetric"));
    }
}

} // namespace

TEST_CASE("gradF samples: keepPending() with the material's changed flags leaves what it "
          "holds, keeps no record for the initial state, stops a state it cannot keep",
          "[samples][memory]")
{
    changedFlagsKeepWithoutComparing<1>();
    changedFlagsKeepWithoutComparing<2>();
    changedFlagsKeepWithoutComparing<3>();
}

TEST_CASE("gradF samples in the initial state keep no record and read as that state",
          "[samples][memory]")
{
    initialSamplesKeepNoRecord<2>();
    initialSamplesKeepNoRecord<3>();
}

TEST_CASE("gradF samples: the commit in place leaves the states the copy did", "[samples][memory]")
{
    commitInPlaceIsTheCopy<1>();
    commitInPlaceIsTheCopy<2>();
    commitInPlaceIsTheCopy<3>();
}

TEST_CASE("gradF samples follow a changed list: kept pairs keep their state, new ones start from "
          "their owner's",
          "[samples][memory]")
{
    followKeepsAndStartsStates<2>();
    followKeepsAndStartsStates<3>();
}

TEST_CASE("gradF samples: the restart field round-trips bit for bit in the packed layout",
          "[samples][memory]")
{
    restartFieldRoundTrips<2>();
    restartFieldRoundTrips<3>();
}

TEST_CASE("a plastic state's compact form unpacks bit for bit", "[samples][memory]")
{
    compactFormIsExact<1>();
    compactFormIsExact<2>();
    compactFormIsExact<3>();
}

TEST_CASE("StatePool: records keep address and contents as it grows, released ones are reused",
          "[samples][memory]")
{
    StatePool pool;
    pool.reset(3);
    std::vector<StatePool::Index> records;
    std::vector<const double*> addresses;
    for (int i = 0; i < 10000; ++i) // more than two blocks
    {
        records.push_back(pool.allocate());
        double* r = pool.at(records.back());
        r[0] = i;
        r[1] = -i;
        r[2] = 0.5 * i;
        addresses.push_back(r);
    }
    CHECK(pool.held() == 10000);
    for (int i = 0; i < 10000; ++i)
    {
        const double* r = pool.at(records[static_cast<std::size_t>(i)]);
        REQUIRE(r == addresses[static_cast<std::size_t>(i)]);
        REQUIRE((r[0] == i && r[1] == -i && r[2] == 0.5 * i));
    }
    pool.release(records[17]);
    pool.release(records[4242]);
    CHECK(pool.held() == 9998);
    const StatePool::Index again = pool.allocate();
    CHECK((again == records[17] || again == records[4242]));
    CHECK(pool.held() == 9999);
    // releaseAll(): every record let go, and handed out again from 0 in the same memory (the
    // pending states' list, refilled every step, neither copies nor allocates).
    pool.releaseAll();
    CHECK(pool.held() == 0);
    CHECK(pool.extent() == 0);
    for (int i = 0; i < 10000; ++i)
    {
        const StatePool::Index index = pool.allocate();
        REQUIRE(index == static_cast<StatePool::Index>(i));
        REQUIRE(pool.at(index) == addresses[static_cast<std::size_t>(i)]);
    }
    pool.reset(3);
    CHECK(pool.held() == 0);
    CHECK(pool.allocate() == 0);
}

TEST_CASE("StatePool: relocate() moves the held records to their destinations, in place",
          "[samples][memory]")
{
    StatePool pool;
    pool.reset(2);
    const std::size_t count = 9000; // more than two blocks
    for (std::size_t i = 0; i < count; ++i)
    {
        double* r = pool.at(pool.allocate());
        r[0] = static_cast<double>(i);
        r[1] = -static_cast<double>(i);
    }
    // Every third record released; the others go to a random order of 0 .. held − 1.
    std::vector<StatePool::Index> destination(count, StatePool::none);
    std::vector<StatePool::Index> order;
    for (std::size_t i = 0; i < count; ++i)
    {
        if (i % 3 == 1)
        {
            pool.release(static_cast<StatePool::Index>(i));
        }
        else
        {
            order.push_back(static_cast<StatePool::Index>(order.size()));
        }
    }
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    std::vector<double> expected(2 * order.size());
    for (std::size_t i = 0, next = 0; i < count; ++i)
    {
        if (i % 3 != 1)
        {
            destination[i] = order[next++];
            expected[2 * destination[i]] = static_cast<double>(i);
            expected[2 * destination[i] + 1] = -static_cast<double>(i);
        }
    }
    const std::size_t held = pool.held();
    CHECK(pool.allocatedSinceOrdered() == count);
    pool.relocate(destination);
    CHECK(pool.held() == held);
    CHECK(pool.extent() == held);
    CHECK(pool.allocatedSinceOrdered() == 0);
    for (std::size_t k = 0; k < held; ++k)
    {
        const double* r = pool.at(static_cast<StatePool::Index>(k));
        REQUIRE((r[0] == expected[2 * k] && r[1] == expected[2 * k + 1]));
    }
    // Nothing is free after it: the next record is a new one, after the held ones.
    CHECK(pool.allocate() == held);
    // A destination list of the wrong length is refused.
    std::vector<StatePool::Index> wrong(3, StatePool::none);
    CHECK_THROWS_AS(pool.relocate(wrong), std::logic_error);
}

// Bodies of j2Plasticity and druckerPrager in one case share the samples' store: one packed
// layout, and the records in druckerPrager's compact form, the wider (it keeps the flow
// pressure, plasticity.md (P9.7)), whichever material is declared first.
TEST_CASE("gradF samples of j2Plasticity and druckerPrager bodies share one store that keeps the "
          "flow pressure",
          "[samples][memory]")
{
    constexpr int D = 3;
    const char* kDP = "type druckerPrager; E 2.5; nu 0.3; rho 1; frictionAngle 30;";
    for (const bool j2First : {true, false})
    {
        INFO("j2Plasticity declared first: " << j2First);
        ParticleFields<D> fields;
        fields.setSize(2);
        const auto j2 = test::build<Material<D>>(kJ2, {&fields, BodyRange{"metal", 0, 1}, nullptr}, D);
        const auto dp = test::build<Material<D>>(kDP, {&fields, BodyRange{"sand", 1, 2}, nullptr}, D);
        REQUIRE(j2->historyComponents() == dp->historyComponents());
        REQUIRE(dp->compactHistoryComponents() == j2->compactHistoryComponents() + 1);
        SampleHistory<D> history;
        if (j2First)
        {
            history.declare({j2.get(), dp.get()}, fields);
        }
        else
        {
            history.declare({dp.get(), j2.get()}, fields);
        }
        // Two samples each: a flowing sand state (its flow pressure set), and the initial state.
        std::mt19937 random(3);
        std::vector<double> sand = randomState<D>(random);
        sand[PlasticState<D>::flowPressureAt] = -1234.5;
        const std::size_t width = history.width();
        std::vector<double> values(4 * width, 0.0);
        for (std::size_t k = 0; k < 4; ++k)
        {
            values[k * width] = static_cast<double>(k % 2); // the neighbour's index
            std::vector<double> state(PlasticState<D>::packedSize);
            if (k == 1)
            {
                state = sand;
            }
            else
            {
                PlasticState<D>{}.pack(state.data());
            }
            std::copy(state.begin(), state.end(), &values[k * width + 1]);
        }
        history.assign({2, 2}, values);
        CHECK(history.storedStates() == 1);
        std::vector<double> back(4 * width);
        history.get(0, back.data());
        history.get(1, back.data() + 2 * width);
        CHECK(sameBits(back.data(), values.data(), values.size()));
    }
}
