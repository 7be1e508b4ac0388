// The reader of the function objects' tables (io/DatTable) against their writer
// (functionObjects/DatFile), and its messages for tables it cannot use.
#include "functionObjects/DatFile.hpp"
#include "io/DatTable.hpp"
#include "support/TestSupport.hpp"

#include <cmath>
#include <limits>

using namespace sph;
using sph::test::requireInputError;

TEST_CASE("dat table: reads back what DatFile writes, also after a restart", "[datTable]")
{
    test::TempDir dir;
    const auto file = dir.path() / "postProcessing" / "tip" / "tip.dat";
    std::filesystem::create_directories(file.parent_path());
    {
        DatFile out(file, {"u_numeric", "u_exact"});
        out.open(0.0, false);
        out.write(0.0, {0.0, 0.0});
        out.write(1e-3, {1.25e-4, -3.5});
        out.write(2e-3, {std::numeric_limits<double>::quiet_NaN(), 1e300});
    }
    {
        // A restart at 2 ms keeps the rows before it and writes the rest again.
        DatFile out(file, {"u_numeric", "u_exact"});
        out.open(2e-3, true);
        out.write(2e-3, {0.125, 7.0});
    }
    const DatTable table = readDatTable(file);
    CHECK(table.file == file);
    CHECK(table.columns == std::vector<std::string>{"time", "u_numeric", "u_exact"});
    REQUIRE(table.rows.size() == 3);
    CHECK(table.column("time") == std::vector<double>{0.0, 1e-3, 2e-3});
    CHECK(table.column("u_numeric") == std::vector<double>{0.0, 1.25e-4, 0.125});
    CHECK(table.column("u_exact") == std::vector<double>{0.0, -3.5, 7.0});
    CHECK(table.column("3") == table.column("u_exact")); // by 1-based number
    CHECK(table.columnAt(0) == table.column("time"));
    CHECK(table.hasColumn("u_exact"));
    CHECK_FALSE(table.hasColumn("u_error"));

    // nan and inf are numbers in a table (a diverged run writes them).
    const auto special = dir.write("special.dat", "# time x\n0 nan\n1 -inf\n");
    const auto x = readDatTable(special).column("x");
    CHECK(std::isnan(x[0]));
    CHECK(x[1] == -std::numeric_limits<double>::infinity());
}

TEST_CASE("dat table: a missing column names the file, the columns and the closest",
          "[datTable][errors]")
{
    test::TempDir dir;
    const auto file = dir.write("energy.dat", "# time kinetic strain drift\n0 1 0 0\n");
    const DatTable table = readDatTable(file);
    try
    {
        table.column("drfit");
        FAIL("expected an InputError");
    }
    catch (const InputError& error)
    {
        const std::string text = error.what();
        INFO(text);
        CHECK_THAT(text, Catch::Contains(file.string() + ": no column 'drfit'"));
        CHECK_THAT(text, Catch::Contains("Columns (4): time, kinetic, strain, drift"));
        CHECK_THAT(text, Catch::Contains("Did you mean 'drift'?"));
    }
    CHECK_THROWS_AS(table.column("5"), InputError); // past the last column by number
    CHECK_THROWS_AS(table.columnAt(4), std::out_of_range);
}

TEST_CASE("dat table: a malformed row is reported at its line and value", "[datTable][errors]")
{
    test::TempDir dir;
    SECTION("a value that is not a number")
    {
        const auto file = dir.write("t.dat", "# time a b\n0 1 2\n\n1 1.5x 2\n");
        const std::string text = requireInputError([&] { readDatTable(file); }, 4, 3,
                                                   "'1.5x' is not a number (column 'a')");
        CHECK_THAT(text, Catch::Contains(file.string() + ":4:3:"));
        CHECK_THAT(text, Catch::Contains("    1 1.5x 2\n      ^~~~"));
    }
    SECTION("a row with too few values")
    {
        const auto file = dir.write("t.dat", "# time a b\n0 1 2\n1 1\n");
        const std::string text = requireInputError([&] { readDatTable(file); }, 3, 3,
                                                   "a row of 2 values in a table of 3 columns");
        CHECK_THAT(text, Catch::Contains("Columns: time, a, b"));
    }
    SECTION("a row with too many values points at the first extra one")
    {
        const auto file = dir.write("t.dat", "# time a\n0 1\n1 2 3\n");
        requireInputError([&] { readDatTable(file); }, 3, 5,
                          "a row of 3 values in a table of 2 columns");
    }
    SECTION("rows without a header")
    {
        const auto file = dir.write("t.dat", "\n0 1 2\n");
        requireInputError([&] { readDatTable(file); }, 2, 1, "a row before the header line");
        // A hand-written reference table may leave it out: its columns are then numbered.
        const DatTable table = readDatTable(file, DatHeader::optional);
        CHECK(table.columns == std::vector<std::string>{"1", "2", "3"});
        CHECK(table.column("3") == std::vector<double>{2.0});
    }
    SECTION("an empty file")
    {
        const auto file = dir.write("t.dat", "");
        requireInputError([&] { readDatTable(file); }, 1, 1, "an empty table: no header line");
    }
    SECTION("a file that does not exist")
    {
        CHECK_THROWS_AS(readDatTable(dir.path() / "missing.dat"), InputError);
    }
}

TEST_CASE("dat table: a header without rows is an empty table", "[datTable]")
{
    test::TempDir dir;
    const auto file = dir.write("t.dat", "# time a b\n# a later comment line\n");
    const DatTable table = readDatTable(file);
    CHECK(table.columns == std::vector<std::string>{"time", "a", "b"});
    CHECK(table.rows.empty());
    CHECK(table.column("b").empty());
}
