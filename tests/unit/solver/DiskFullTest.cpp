// A full disk (issue 12, item 8): a file that cannot be written stops the run with an I/O error
// (exit 4) naming the file the user knows and the system's reason, and never replaces a good
// file with a damaged one; a table keeps whole rows; the temporaries of a killed run go at the
// next start. The disk is "full" through a file-size limit (RLIMIT_FSIZE, with SIGXFSZ ignored,
// writes past it fail with EFBIG "File too large"): portable, nothing to mount, and inherited
// by the solver run as a child process.
#include "core/IoError.hpp"
#include "functionObjects/DatFile.hpp"
#include "io/AtomicFile.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <signal.h>
#include <sys/resource.h>

#include <fstream>
#include <sstream>

using namespace sph;

namespace
{

const std::string schemes = "kernel { type cubicSpline; }\nformulation { type totalLagrangian; }\n"
                            "stabilisation { type none; }";

// While alive, no file of this process (or of the processes it starts) can grow past `bytes`.
class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        REQUIRE(getrlimit(RLIMIT_FSIZE, &saved_) == 0);
        handler_ = signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &saved_);
        signal(SIGXFSZ, handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit saved_{};
    sighandler_t handler_ = SIG_DFL;
};

// Every file under `folder` whose name holds ".tmp" (our temporaries: ".<name>.tmp<pid>").
std::vector<std::string> temporariesUnder(const std::filesystem::path& folder)
{
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    {
        if (entry.path().filename().string().find(".tmp") != std::string::npos)
        {
            found.push_back(entry.path().string());
        }
    }
    return found;
}

// The block case with no function objects: its outputs are the .vtu files and the .pvd only.
std::filesystem::path writeOutputOnlyCase(const std::filesystem::path& folder)
{
    const auto caseDir = test::writeBlockCase(folder, schemes, 1e-3, 1e-4);
    std::ofstream(caseDir / "system" / "controlDict")
        << "endTime 1e-3;\ncourant 0.3;\nwriteInterval 1e-4;\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    return caseDir;
}

// Output `index` of the block case.
std::filesystem::path vtu(const std::filesystem::path& caseDir, int index)
{
    return caseDir / "VTK" / ("block_" + std::to_string(index) + ".vtu");
}

} // namespace

TEST_CASE("a failed atomic write names the target, keeps the old file, leaves no temporary",
          "[output][diskFull]")
{
    test::TempDir dir;
    const auto target = dir.write("postProcessing/summary.json", "good\n");
    const std::string big(4096, 'x');
    try
    {
        const FileSizeLimit limit(1024);
        writeTextAtomically(target, big);
        FAIL("no error for a write past the file-size limit");
    }
    catch (const IoError& error)
    {
        CHECK(std::string(error.what()) == target.string() + ": cannot write: File too large");
    }
    CHECK(test::fileText(target) == "good\n");
    CHECK(temporariesUnder(dir.path()).empty());
}

TEST_CASE("a table row that cannot be written stops the run, the table keeps whole rows",
          "[output][diskFull]")
{
    test::TempDir dir;
    const auto file = dir.path() / "energy" / "energy.dat";
    DatFile table(file, {"kinetic", "strain"});
    table.open(0.0, false);
    int rows = 0;
    try
    {
        const FileSizeLimit limit(1000);
        for (; rows < 1000; ++rows)
        {
            table.write(rows * 1e-5, {1.0 / 3.0, 2.0 / 3.0});
        }
        FAIL("no error for a row past the file-size limit");
    }
    catch (const IoError& error)
    {
        CHECK(std::string(error.what()) == file.string() + ": cannot write: File too large");
    }
    const DatTable written = readDatTable(file); // whole rows only: a cut row would not read
    CHECK(static_cast<int>(written.rows.size()) == rows);
    CHECK(rows > 5);
}

TEST_CASE("a .vtu that cannot be written stops the run with exit 4, earlier ones are intact",
          "[output][diskFull]")
{
    // A run without the limit gives the sizes of the outputs; the limit is set so that the
    // first output fits and a later one does not (the initial state compresses better).
    test::TempDir one;
    test::TempDir two;
    const auto free = writeOutputOnlyCase(one.path() / "block");
    REQUIRE(test::runProcess("sphSolid", {"-case", free.string()}) == 0);
    const std::uintmax_t limit = std::filesystem::file_size(vtu(free, 0)) + 16;
    int failing = 1;
    while (std::filesystem::exists(vtu(free, failing)) &&
           std::filesystem::file_size(vtu(free, failing)) <= limit)
    {
        ++failing;
    }
    REQUIRE(std::filesystem::exists(vtu(free, failing)));
    INFO("outputs 0 to " << failing - 1 << " fit in " << limit << " bytes");

    const auto full = writeOutputOnlyCase(two.path() / "block");
    std::string output;
    int status = 0;
    {
        const FileSizeLimit fileSize(limit);
        status = test::runProcess("sphSolid", {"-case", full.string()}, &output);
    }
    INFO(output);
    CHECK(status == 4);
    CHECK_THAT(output, Catch::Contains("FATAL I/O ERROR"));
    CHECK_THAT(output, Catch::Contains(vtu(full, failing).string() + ": cannot write: File too large"));
    CHECK_THAT(output, !Catch::Contains("INPUT ERROR") && !Catch::Contains(".tmp"));
    CHECK(!std::filesystem::exists(vtu(full, failing)));
    for (int index = 0; index < failing; ++index)
    {
        INFO("output " << index);
        CHECK(readVtu(vtu(full, index)).pointCount() == 100);
        CHECK(test::fileText(vtu(full, index)) == test::fileText(vtu(free, index)));
    }
    PvdSeries series(full / "VTK" / "block.pvd");
    series.load();
    CHECK(static_cast<int>(series.entries().size()) == failing);
    CHECK(temporariesUnder(full).empty());
}

TEST_CASE("a restart that cannot write its level again keeps that level in the series",
          "[output][diskFull][restart]")
{
    // Issue 31 item 6: with the disk still full, a restart from level 4 failed rewriting
    // level 4; the series then listed 0 to 3 though level 4 was intact, and the next restart
    // started from 3 and deleted level 4.
    test::TempDir one;
    test::TempDir two;
    const auto free = writeOutputOnlyCase(one.path() / "block");
    REQUIRE(test::runProcess("sphSolid", {"-case", free.string()}) == 0);
    const auto stopped = writeOutputOnlyCase(two.path() / "block");
    REQUIRE(test::runSolver(stopped, {"-set", "endTime=4e-4"}) == 0);
    const std::string level4 = test::fileText(vtu(stopped, 4));
    const auto listed = [&]
    {
        PvdSeries series(stopped / "VTK" / "block.pvd");
        series.load();
        std::vector<std::string> files;
        for (const auto& entry : series.entries())
        {
            files.push_back(entry.file);
        }
        return files;
    };
    const std::vector<std::string> levels{"block_0.vtu", "block_1.vtu", "block_2.vtu",
                                          "block_3.vtu", "block_4.vtu"};
    REQUIRE(listed() == levels);
    // Room for the series and the log, not for level 4 again; twice, as a user retries.
    for (int attempt = 0; attempt < 2; ++attempt)
    {
        INFO("attempt " << attempt);
        std::string output;
        int status = 0;
        {
            const FileSizeLimit fileSize(level4.size() - 1);
            status = test::runProcess("sphSolid",
                                      {"-case", stopped.string(), "-set",
                                       "controlDict.startFrom=latestTime"},
                                      &output);
        }
        INFO(output);
        CHECK(status == 4);
        CHECK_THAT(output, Catch::Contains("Restart     from block_4.vtu"));
        CHECK_THAT(output, Catch::Contains("block_4.vtu: cannot write: File too large"));
        CHECK(listed() == levels);
        CHECK(test::fileText(vtu(stopped, 4)) == level4);
        CHECK(temporariesUnder(stopped).empty());
    }
    // With room again, the run continues from level 4 as if never interrupted.
    REQUIRE(test::runSolver(stopped, {"-set", "controlDict.startFrom=latestTime"}) == 0);
    PvdSeries series(stopped / "VTK" / "block.pvd");
    series.load();
    PvdSeries reference(free / "VTK" / "block.pvd");
    reference.load();
    REQUIRE(series.entries().size() == reference.entries().size());
    for (std::size_t index = 0; index < reference.entries().size(); ++index)
    {
        INFO("output " << index);
        CHECK(series.entries()[index].file == reference.entries()[index].file);
        CHECK(test::fileText(vtu(stopped, static_cast<int>(index))) ==
              test::fileText(vtu(free, static_cast<int>(index))));
    }
}

TEST_CASE("the temporaries a killed run left are removed when the run starts again",
          "[output][restart]")
{
    test::TempDir dir;
    const auto caseDir = test::writeBlockCase(dir.path() / "block", schemes, 2e-4, 1e-4);
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir) == 0);
    // Process 999999999 cannot exist (Linux process ids stay below 2^22).
    const std::vector<std::filesystem::path> stale{
        caseDir / "VTK" / ".block_3.vtu.tmp999999999",
        caseDir / "VTK" / ".block.pvd.tmp999999999",
        caseDir / "postProcessing" / "energy" / ".energy.dat.tmp999999999"};
    // Not ours, or of a process that still runs: kept.
    const std::vector<std::filesystem::path> kept{
        caseDir / "VTK" / "notes.tmp999999999",
        caseDir / "postProcessing" / (".summary.json.tmp" + std::to_string(getppid()))};
    for (const auto& file : stale)
    {
        std::ofstream(file) << "<VTKFile";
    }
    for (const auto& file : kept)
    {
        std::ofstream(file) << "mine";
    }
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=3e-4", "-set",
                                      "controlDict.startFrom=latestTime"}) == 0);
    for (const auto& file : stale)
    {
        CHECK(!std::filesystem::exists(file));
    }
    for (const auto& file : kept)
    {
        CHECK(std::filesystem::exists(file));
    }
}

TEST_CASE("sphStudy stops with the I/O error of a variant and runs it again when resumed",
          "[output][diskFull][study]")
{
    test::TempDir dir;
    const auto caseDir = writeOutputOnlyCase(dir.path() / "block");
    std::ofstream(caseDir / "system" / "studyDict")
        << "axes { courant { c2 { solver (\"courant=0.2\"); } c3 { solver (\"courant=0.3\"); } } }\n"
           "threads 1;\nmetrics { energyDrift { type summary; value steps; } }\n";
    const auto study = caseDir / "postProcessing" / "study";
    const auto staleTemporary = study / ".results.csv.tmp999999999"; // of a killed study
    std::filesystem::create_directories(study);
    std::ofstream(staleTemporary) << "a,b";

    // Room for the copied case, the particle file and the logs, not for the solver's output.
    const std::uintmax_t particles = std::filesystem::file_size(caseDir / "constant" / "particles.vtu");
    std::string output;
    int status = 0;
    {
        const FileSizeLimit fileSize(particles + 64);
        status = test::runProcess("sphStudy", {"-case", caseDir.string()}, &output);
    }
    INFO(output);
    CHECK(status == 4);
    CHECK_THAT(output, Catch::Contains("FATAL I/O ERROR"));
    CHECK_THAT(output, Catch::Contains("c2_0.vtu: cannot write: File too large"));
    CHECK_THAT(output, Catch::Contains("sphSolid of the variant c2"));
    CHECK_THAT(output, !Catch::Contains("[2/2]")); // the next variant would meet the same disk
    CHECK(!std::filesystem::exists(study / "runs" / "c2" / "study.json"));
    CHECK(!std::filesystem::exists(staleTemporary));

    output.clear();
    REQUIRE(test::runProcess("sphStudy", {"-case", caseDir.string()}, &output) == 0);
    CHECK_THAT(output, Catch::Contains("[1/2] c2: finished"));
    CHECK_THAT(output, Catch::Contains("[2/2] c3: finished"));
}
