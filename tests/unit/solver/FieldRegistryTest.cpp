// The per-particle field registry (particles/ParticleFields.hpp) and the state file written
// from it (solver/StateFile.hpp): declarations, the file layout ParaView sees, and an exact
// round trip of every kind of restart field in 1D, 2D and 3D.
#include "io/PvtuFile.hpp"
#include "io/VtuFile.hpp"
#include "solver/StateFile.hpp"
#include "support/TestSupport.hpp"

#include <fstream>
#include <random>

using namespace sph;

TEST_CASE("field declarations: file names, roles and impossible combinations", "[fields]")
{
    const FieldSpec shown = FieldSpec::vector("velocity", "v [m/s]").display();
    const FieldSpec hidden = FieldSpec::vector("velocityHalfStep", "v^{n-1/2} [m/s]").restart();
    const FieldSpec both = FieldSpec::scalar("plasticStrain", "history").restart().display();
    CHECK(shown.fileName() == "velocity");
    CHECK(hidden.fileName() == "restart:velocityHalfStep");
    CHECK(both.fileName() == "plasticStrain");
    CHECK(FieldSpec::scalar("work", "scratch").isScratch());
    CHECK(both.describe() == "plasticStrain  scalar, restart + display: history");

    CHECK_THROWS_AS(FieldSpec::scalar("x", "").restart().singlePrecision(), std::logic_error);
    CHECK_THROWS_AS(FieldSpec::thirdOrderTensor("K", "").display(), std::logic_error);
    CHECK_THROWS_AS(FieldSpec::scalar("J", "").active(), std::logic_error); // not displayed
    CHECK_THROWS_AS(FieldSpec::scalar("two words", ""), std::logic_error);
    CHECK_THROWS_AS(FieldSpec::scalar("restart:x", ""), std::logic_error);
}

TEST_CASE("the registry: bound, owned and derived fields", "[fields]")
{
    ParticleFields<2> fields;
    fields.setSize(4);
    std::vector<Vec<2>> x(4, Vec<2>::Ones());
    fields.bind(FieldSpec::vector("position", "x").restart().display(), x);
    const FieldSpec historySpec = FieldSpec::scalar("history", "h").restart().display();
    std::vector<double>& history = fields.declare<double>(historySpec, 7.0);
    CHECK(history == std::vector<double>(4, 7.0));
    // A second model instance declaring the same field shares the array.
    CHECK(&fields.declare<double>(historySpec) == &history);
    fields.derive<double>(FieldSpec::scalar("sum", "x + y").display(),
                          [&](std::size_t a) { return x[a].sum(); });

    CHECK_THROWS_AS(fields.bind(FieldSpec::scalar("position", "again"), history), std::logic_error);
    CHECK_THROWS_AS(fields.declare<double>(FieldSpec::vector("wrongKind", "")), std::logic_error);
    CHECK_THROWS_AS(fields.derive<double>(FieldSpec::scalar("restartDerived", "").restart(),
                                          [](std::size_t) { return 0.0; }),
                    std::logic_error);

    double value[4];
    fields.find("sum")->array->get(2, value);
    CHECK(value[0] == 2.0);
    // Resizing reaches bound and owned arrays; new particles get each field's fill value.
    fields.resize(6);
    CHECK(x.size() == 6);
    CHECK(history.size() == 6);
    CHECK(history[5] == 7.0);
    CHECK(x[5] == Vec<2>::Zero());
}

namespace
{

// Every kind of field, filled with random numbers (restart and display), written to a file,
// read back into zeroed arrays: the restart fields come back bit for bit.
template <int D>
void roundTrip(const std::filesystem::path& file)
{
    const std::size_t n = 5;
    std::mt19937 random(D);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    struct Arrays
    {
        std::vector<Vec<D>> x, v;
        std::vector<double> s;
        std::vector<int> id;
        std::vector<std::uint8_t> flag;
        std::vector<Mat<D>> F, P;
        std::vector<Tensor3<D>> K;
    };
    const auto fill = [&](Arrays& arrays, bool zero) {
        const auto r = [&] { return zero ? 0.0 : uniform(random); };
        arrays.x.assign(n, Vec<D>::Zero());
        arrays.v = arrays.x;
        arrays.s.assign(n, 0.0);
        arrays.id.assign(n, 0);
        arrays.flag.assign(n, 0);
        arrays.F.assign(n, Mat<D>::Zero());
        arrays.P = arrays.F;
        arrays.K.assign(n, Tensor3<D>::zero());
        for (std::size_t a = 0; a < n; ++a)
        {
            arrays.x[a] = arrays.x[a].unaryExpr([&](double) { return r(); });
            arrays.v[a] = arrays.v[a].unaryExpr([&](double) { return r(); });
            arrays.s[a] = r();
            arrays.id[a] = zero ? 0 : static_cast<int>(a) - 2;
            arrays.flag[a] = zero ? 0 : static_cast<std::uint8_t>(a % 2);
            arrays.F[a] = arrays.F[a].unaryExpr([&](double) { return r(); });
            arrays.P[a] = arrays.P[a].unaryExpr([&](double) { return r(); });
            for (auto& slice : arrays.K[a].slice)
            {
                slice = slice.unaryExpr([&](double) { return r(); });
            }
        }
    };
    const auto declare = [](ParticleFields<D>& fields, Arrays& arrays) {
        fields.setSize(n);
        fields.bind(FieldSpec::vector(positionField, "x").restart().display(), arrays.x);
        fields.bind(FieldSpec::vector("velocity", "v").restart().display().active(), arrays.v);
        fields.bind(FieldSpec::scalar("volume", "s").restart(), arrays.s);
        fields.bind(FieldSpec::integer("id", "i").restart().display(), arrays.id);
        fields.bind(FieldSpec::integer("flag", "f").restart(), arrays.flag);
        fields.bind(FieldSpec::tensor("F", "F").restart().display().padding(TensorPadding::identity),
                    arrays.F);
        fields.bind(FieldSpec::tensor("P", "P").display().singlePrecision(), arrays.P);
        fields.bind(FieldSpec::thirdOrderTensor("K", "K").restart(), arrays.K);
    };
    Arrays written;
    fill(written, false);
    ParticleFields<D> out;
    declare(out, written);
    long step = 42;
    double deltaT = uniform(random);
    bool flag = true;
    RunScalars outScalars;
    outScalars.bind("step", step);
    outScalars.bind("deltaT", deltaT);
    outScalars.bind("flag", flag);
    VtuData data;
    writeState<D>(out, outScalars, 0.5, data);
    writeVtu(file, data);

    const VtuData read = readVtu(file);
    // The layout ParaView sees.
    CHECK(read.activeVectors == "velocity");
    CHECK(read.pointData.at("velocity").components == 3);
    CHECK(read.pointData.at("F").components == 9);
    CHECK(read.pointData.at("F").componentNames.at(8) == "ZZ");
    CHECK(read.pointData.at("P").readFromSingles);
    CHECK(!read.pointData.at("F").readFromSingles);
    CHECK(read.pointData.at("restart:volume").components == 1);
    CHECK(read.pointData.at("restart:K").components == D * D * D);
    CHECK(read.pointData.count("position") == 0); // the points
    CHECK(read.fieldData.at("TimeValue").values.at(0) == 0.5);
    CHECK(read.fieldData.at("restart:step").values.at(0) == 42.0);
    for (std::size_t a = 0; a < n; ++a)
    {
        const auto& v = read.pointData.at("velocity").values;
        const auto& F = read.pointData.at("F").values;
        const auto& P = read.pointData.at("P").values;
        for (int c = D; c < 3; ++c)
        {
            CHECK(v[3 * a + static_cast<std::size_t>(c)] == 0.0);
            CHECK(F[9 * a + static_cast<std::size_t>(4 * c)] == 1.0); // identity padding
            CHECK(P[9 * a + static_cast<std::size_t>(4 * c)] == 0.0); // zero padding
        }
        CHECK(F[9 * a + 1] == (D > 1 ? written.F[a](0, 1) : 0.0)); // row-major
    }

    Arrays back;
    fill(back, true);
    ParticleFields<D> in;
    declare(in, back);
    long stepBack = 0;
    double deltaTBack = 0.0;
    bool flagBack = false;
    RunScalars inScalars;
    inScalars.bind("step", stepBack);
    inScalars.bind("deltaT", deltaTBack);
    inScalars.bind("flag", flagBack);
    readState<D>(read, in, inScalars, file.string());
    CHECK(back.x == written.x);
    CHECK(back.v == written.v);
    CHECK(back.s == written.s);
    CHECK(back.id == written.id);
    CHECK(back.flag == written.flag);
    CHECK(back.F == written.F);
    CHECK(back.P == std::vector<Mat<D>>(n, Mat<D>::Zero())); // display only: not read
    for (std::size_t a = 0; a < n; ++a)
    {
        for (int k = 0; k < D; ++k)
        {
            CHECK(back.K[a].slice[static_cast<std::size_t>(k)] ==
                  written.K[a].slice[static_cast<std::size_t>(k)]);
        }
    }
    CHECK(stepBack == 42);
    CHECK(deltaTBack == deltaT);
    CHECK(flagBack);

    // The same state streamed into the file in pieces of 2 particles (3 pieces, the last one
    // short; how a run writes its output): one dataset again, every array equal, in order.
    VtuData header;
    writeStateHeader<D>(out, outScalars, 0.5, header);
    const std::filesystem::path pieced = file.parent_path() / ("pieced_" + file.filename().string());
    int piecesMade = 0;
    writeVtuInPieces(pieced, header, n,
                     [&](std::size_t begin, std::size_t end, VtuData& piece) {
                         CHECK(end - begin == (begin == 4 ? 1u : 2u));
                         ++piecesMade;
                         writeStatePoints<D>(out, nullptr, begin, end, piece);
                     },
                     2);
    CHECK(piecesMade == 3);
    const VtuData readPieced = readVtu(pieced);
    CHECK(readPieced.points == read.points);
    CHECK(readPieced.activeVectors == read.activeVectors);
    REQUIRE(readPieced.pointData.size() == read.pointData.size());
    for (const auto& [name, array] : read.pointData)
    {
        INFO(name);
        CHECK(readPieced.pointData.at(name).values == array.values);
        CHECK(readPieced.pointData.at(name).components == array.components);
        CHECK(readPieced.pointData.at(name).readFromSingles == array.readFromSingles);
    }
    REQUIRE(readPieced.fieldData.size() == read.fieldData.size());
    for (const auto& [name, array] : read.fieldData)
    {
        INFO(name);
        CHECK(readPieced.fieldData.at(name).values == array.values);
    }
    // A selection writes those particles, in its order.
    const std::vector<std::size_t> selection{4, 1};
    VtuData selected;
    writeStatePoints<D>(out, &selection, 0, 2, selected);
    // A stored field of doubles is not copied into the piece: the writer streams it from the
    // fields (what materialise() gives is what the file gets).
    VtuArray volume = selected.pointData.at("restart:volume");
    CHECK(volume.values.empty());
    REQUIRE(volume.streamed);
    CHECK(volume.size() == 2u);
    materialise(volume);
    CHECK(volume.values == std::vector<double>{written.s[4], written.s[1]});

    // A file without one of the restart arrays, or with another shape, is an input error
    // naming the file and the array.
    VtuData missing = read;
    missing.pointData.erase("restart:K");
    CHECK_THROWS_WITH(readState<D>(missing, in, inScalars, "old.vtu"),
                      Catch::Contains("cannot restart from 'old.vtu': it has no array 'restart:K'"));
    VtuData reshaped = read;
    reshaped.pointData.at("velocity").components = 1;
    CHECK_THROWS_WITH(readState<D>(reshaped, in, inScalars, "other.vtu"),
                      Catch::Contains("'velocity' has 1 components, not 3"));
}

} // namespace

TEST_CASE("the state file restores every kind of restart field exactly", "[fields]")
{
    test::TempDir dir;
    roundTrip<1>(dir.path() / "one.vtu");
    roundTrip<2>(dir.path() / "two.vtu");
    roundTrip<3>(dir.path() / "three.vtu");
}

// A ragged field (a variable number of entries per particle: gradF's per-sample history):
// its counts are point data, its entries field data in the written particles' order; a
// distributed run's pieces are joined back in global order with each particle's entries.
TEST_CASE("the state file restores a ragged field whole and from the pieces of a distributed run",
          "[fields]")
{
    constexpr std::size_t n = 7;
    const auto entriesOf = [](std::size_t g) {
        std::vector<double> values;
        for (std::size_t e = 0; e < g % 4; ++e) // particles 0 and 4 have none
        {
            values.insert(values.end(), {static_cast<double>(g), 0.1 * e, std::sqrt(g + 0.3 * e)});
        }
        return values;
    };
    struct Particles
    {
        ParticleFields<2> fields;
        std::vector<Vec<2>> x;
        std::vector<int> id;
        RaggedVectors samples{"samples", 3};
        explicit Particles(std::size_t count) : x(count, Vec<2>::Zero()), id(count, 0)
        {
            fields.bind(FieldSpec::vector(positionField, "x").restart().display(), x);
            fields.bind(FieldSpec::integer("globalId", "id").restart().display(), id);
            fields.setSize(count);
            fields.bindRagged(samples);
            samples.values.resize(count);
        }
    };
    Particles written(n);
    for (std::size_t g = 0; g < n; ++g)
    {
        written.x[g] = Vec<2>(0.5 * g, -1.0 * g);
        written.id[g] = static_cast<int>(g);
        written.samples.values[g] = entriesOf(g);
    }
    RunScalars scalars;
    test::TempDir dir;
    const auto check = [&](const VtuData& data, const std::string& file) {
        Particles back(n);
        readState<2>(data, back.fields, scalars, file);
        CHECK(back.x == written.x);
        CHECK(back.samples.values == written.samples.values);
    };

    SECTION("one file")
    {
        VtuData data;
        writeState<2>(written.fields, scalars, 0.0, data);
        CHECK(data.pointData.at("restart:samplesCount").values ==
              std::vector<double>{0, 1, 2, 3, 0, 1, 2});
        CHECK(data.fieldData.at("restart:samples").components == 3);
        CHECK(!data.fieldData.at("restart:samples").streamed); // writeState holds every value
        writeVtu(dir.path() / "whole.vtu", data);
        const VtuData read = readVtu(dir.path() / "whole.vtu");
        check(read, "whole.vtu");

        VtuData miscounted = read;
        miscounted.pointData.at("restart:samplesCount").values[2] = 3.0;
        Particles back(n);
        CHECK_THROWS_WITH(readState<2>(miscounted, back.fields, scalars, "bad.vtu"),
                          Catch::Contains("cannot restart from 'bad.vtu'") &&
                              Catch::Contains("'restart:samples' holds 27 values") &&
                              Catch::Contains("not 10 entries of 3"));
        VtuData negative = read;
        negative.pointData.at("restart:samplesCount").values[1] = -1.0;
        CHECK_THROWS_WITH(readState<2>(negative, back.fields, scalars, "bad.vtu"),
                          Catch::Contains("restart:samplesCount"));
    }

    SECTION("pieces of a distributed run")
    {
        // Rank 0 owned particles 1, 4, 5; rank 1 particles 0, 2, 3, 6 (each in increasing id).
        const std::vector<std::vector<std::size_t>> owned{{1, 4, 5}, {0, 2, 3, 6}};
        std::filesystem::create_directories(dir.path() / "run_0");
        std::vector<std::string> pieces;
        VtuData layout;
        for (std::size_t r = 0; r < owned.size(); ++r)
        {
            VtuData piece;
            writeStateHeader<2>(written.fields, scalars, 0.0, piece, &owned[r]);
            // The entries are not copied into the header: the writer streams them.
            CHECK(piece.fieldData.at("restart:samples").values.empty());
            REQUIRE(piece.fieldData.at("restart:samples").streamed);
            CHECK(piece.fieldData.at("restart:samples").streamed->size() == (r == 0 ? 6u : 21u)); // 2 and 7 entries of 3
            writeStatePoints<2>(written.fields, &owned[r], 0, owned[r].size(), piece);
            pieces.push_back("run_0/run_0_" + std::to_string(r) + ".vtu");
            writeVtu(dir.path() / pieces.back(), piece);
            layout = piece;
        }
        writePvtu(dir.path() / "run_0.pvtu", layout, pieces);
        const VtuData joined = readPvtu(dir.path() / "run_0.pvtu", "globalId");
        check(joined, "run_0.pvtu");

        // A piece of another level (another time): refused, not joined (issue 31).
        {
            VtuData other = readVtu(dir.path() / pieces[1]);
            const VtuData kept = other;
            other.fieldData.at("TimeValue").values[0] += 0.005;
            writeVtu(dir.path() / pieces[1], other);
            CHECK_THROWS_WITH(readPvtu(dir.path() / "run_0.pvtu", "globalId"),
                              Catch::Contains("cannot read") &&
                                  Catch::Contains("its pieces are of different levels: TimeValue"));
            writeVtu(dir.path() / pieces[1], kept);
        }

        // A piece whose entries do not match its counts.
        VtuData damaged = readVtu(dir.path() / pieces[1]);
        damaged.fieldData.at("restart:samples").values.resize(3);
        writeVtu(dir.path() / pieces[1], damaged);
        CHECK_THROWS_WITH(readPvtu(dir.path() / "run_0.pvtu", "globalId"),
                          Catch::Contains("cannot read") && Catch::Contains("'restart:samples'"));
    }
}

// An empty .pvtu, a well-formed one without <PUnstructuredGrid>, a piece without a Source: each
// an input error naming the file (an empty one crashed a latestTime restart, issue 31).
TEST_CASE("a damaged .pvtu is refused with its name, not read", "[output][distributed]")
{
    test::TempDir dir;
    const auto write = [&](const std::string& text)
    {
        std::ofstream(dir.path() / "run_1.pvtu") << text;
        return dir.path() / "run_1.pvtu";
    };
    for (const std::string& text :
         {std::string(), std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\"/>\n"),
          std::string("<VTKFile><PUnstructuredGrid><Piece/></PUnstructuredGrid></VTKFile>\n")})
    {
        INFO("'" << text << "'");
        CHECK_THROWS_WITH(readPvtu(write(text), "globalId"),
                          Catch::Contains("cannot read") && Catch::Contains("run_1.pvtu"));
    }
}
