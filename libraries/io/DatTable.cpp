#include "io/DatTable.hpp"

#include "core/InputError.hpp"
#include "core/Suggest.hpp"
#include "core/TextFile.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace sph
{

namespace
{

struct Word
{
    std::string text;
    int column; // 1-based
};

std::vector<Word> split(const std::string& line)
{
    std::vector<Word> words;
    std::size_t at = 0;
    while ((at = line.find_first_not_of(" \t\r", at)) != std::string::npos)
    {
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        words.push_back({line.substr(at, end - at), static_cast<int>(at) + 1});
        at = end;
    }
    return words;
}

std::string joined(const std::vector<std::string>& words)
{
    std::string text;
    for (const auto& word : words)
    {
        text += (text.empty() ? "" : ", ") + word;
    }
    return text;
}

} // namespace

std::size_t DatTable::columnIndex(const std::string& name) const
{
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
        if (columns[c] == name)
        {
            return c;
        }
    }
    char* end = nullptr;
    const long number = std::strtol(name.c_str(), &end, 10);
    if (!name.empty() && *end == '\0' && number >= 1 &&
        static_cast<std::size_t>(number) <= columns.size())
    {
        return static_cast<std::size_t>(number - 1);
    }
    throw InputError(file.string() + ": no column '" + name + "'",
                     {"Columns (" + std::to_string(columns.size()) + "): " + joined(columns) +
                          " (or their number, 1 to " + std::to_string(columns.size()) + ")",
                      didYouMean(name, columns)});
}

std::vector<double> DatTable::column(const std::string& name) const
{
    return columnAt(columnIndex(name));
}

std::vector<double> DatTable::columnAt(std::size_t index) const
{
    if (index >= columns.size())
    {
        throw std::out_of_range(file.string() + ": no column " + std::to_string(index));
    }
    std::vector<double> values;
    values.reserve(rows.size());
    for (const auto& row : rows)
    {
        values.push_back(row[index]);
    }
    return values;
}

bool DatTable::hasColumn(const std::string& name) const
{
    return std::find(columns.begin(), columns.end(), name) != columns.end();
}

DatTable readDatTable(const std::filesystem::path& file, DatHeader header)
{
    const std::string text =
        readTextFile(file, "the table",
                     {"Function objects write postProcessing/<name>/<name>.dat while the case "
                      "runs; did the run start, and is the function object's name right?"});
    std::shared_ptr<const SourceText> source;
    // The text is split into quotable lines only when there is something to report.
    const auto fail = [&](int line, int column, int length, const std::string& message,
                          std::vector<std::string> notes) -> InputError
    {
        if (!source)
        {
            source = std::make_shared<const SourceText>(file.string(), text);
        }
        return InputError(SourceLocation{source, line, column, length}, message,
                          std::move(notes));
    };

    DatTable table;
    table.file = file;
    bool haveHeader = false;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line))
    {
        ++number;
        const std::vector<Word> words = split(line);
        if (words.empty())
        {
            continue;
        }
        if (words[0].text[0] == '#')
        {
            if (!haveHeader)
            {
                // "# time a b" or "#time a b"
                const std::string first = words[0].text.substr(1);
                if (!first.empty())
                {
                    table.columns.push_back(first);
                }
                for (std::size_t w = 1; w < words.size(); ++w)
                {
                    table.columns.push_back(words[w].text);
                }
                haveHeader = true;
            }
            continue;
        }
        if (!haveHeader)
        {
            if (header == DatHeader::required)
            {
                throw fail(number, 1, static_cast<int>(line.size()),
                           "a row before the header line of column names",
                           {"A table starts with '# time name1 name2 ...' (as the function "
                            "objects write it); is this the right file?"});
            }
            for (std::size_t c = 0; c < words.size(); ++c)
            {
                table.columns.push_back(std::to_string(c + 1));
            }
            haveHeader = true;
        }
        std::vector<double> row;
        row.reserve(words.size());
        for (std::size_t w = 0; w < words.size(); ++w)
        {
            const Word& word = words[w];
            char* end = nullptr;
            const double value = std::strtod(word.text.c_str(), &end);
            if (end != word.text.c_str() + word.text.size())
            {
                const std::string where =
                    w < table.columns.size() ? " (column '" + table.columns[w] + "')" : "";
                throw fail(number, word.column, static_cast<int>(word.text.size()),
                           "'" + word.text + "' is not a number" + where,
                           {"Rows hold numbers only (nan and inf included); a line starting "
                            "with '#' is a comment."});
            }
            row.push_back(value);
        }
        if (row.size() != table.columns.size())
        {
            const bool extra = row.size() > table.columns.size();
            const Word& at = extra ? words[table.columns.size()] : words.back();
            throw fail(number, at.column, static_cast<int>(at.text.size()),
                       "a row of " + std::to_string(row.size()) + " values in a table of " +
                           std::to_string(table.columns.size()) + " columns",
                       {"Columns: " + joined(table.columns),
                        "A run killed while writing can leave a cut last row: delete it, or run "
                        "the case again."});
        }
        table.rows.push_back(std::move(row));
    }
    if (!haveHeader && header == DatHeader::required)
    {
        throw fail(1, 1, 1, "an empty table: no header line of column names",
                   {"A table starts with '# time name1 name2 ...' (as the function objects "
                    "write it); did the run stop before writing it?"});
    }
    return table;
}

} // namespace sph
