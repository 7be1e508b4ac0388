#include "CommandLine.hpp"

#include "InputError.hpp"
#include "Suggest.hpp"

#include <iostream>
#include <sstream>

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif

namespace po = boost::program_options;

namespace sph
{

const char* projectVersion()
{
    return SPH_VERSION;
}

po::typed_value<long>* integerOption(const std::string& name, long min, long max,
                                     const std::string& why)
{
    return po::value<long>()->value_name("N")->notifier(
        [=](long value)
        {
            if (value < min || value > max)
            {
                // Caught in CommandLine::parse, which points at the value.
                throw po::error_with_option_name("-" + name + " " + std::to_string(value) +
                                                     " is outside [" + std::to_string(min) +
                                                     ", " + std::to_string(max) + "]: " + why,
                                                 name);
            }
        });
}

namespace
{

std::string& commandLineOfProcess()
{
    static std::string text;
    return text;
}

// `word` as the shell reads it back: as it is when it holds nothing the shell would split or
// expand, else in single quotes (a quote inside as '\'').
std::string shellQuoted(const std::string& word)
{
    const bool plain = !word.empty() &&
        word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                               "_-+=.,:/@%") == std::string::npos;
    if (plain)
    {
        return word;
    }
    std::string quoted = "'";
    for (const char c : word)
    {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

} // namespace

const std::string& processCommandLine()
{
    return commandLineOfProcess();
}

CommandLine::CommandLine(std::string program, std::string purpose)
    : program_(std::move(program)), purpose_(std::move(purpose)), extra_("Options of " + program_)
{
    InputError::setProgramName(program_);
}

void CommandLine::enableModelOptions(bool listTypes, bool dryRun, bool set)
{
    withListTypes_ = listTypes;
    withDryRun_ = dryRun;
    withSet_ = set;
}

namespace
{

po::options_description commonOptions(bool listTypes, bool dryRun, bool set)
{
    po::options_description common("Common options");
    common.add_options()("case", po::value<std::string>()->value_name("DIR"),
                         "case folder (default: the current folder)");
    if (set)
    {
        common.add_options()(
            "set", po::value<std::vector<std::string>>()->composing()->value_name("KEY=VALUE"),
            "override a dictionary entry after reading, e.g. -set endTime=1e-3 or "
            "-set stabilisation.type=gradF (repeatable; prefix a file name to add a new "
            "top-level key: -set controlDict.startFrom=latestTime)");
    }
    if (listTypes)
    {
        common.add_options()("listTypes",
                             "list every registered model with its description and keys; "
                             "optionally only one family: -listTypes material");
    }
    if (dryRun)
    {
        common.add_options()("dryRun",
                             "read and validate every dictionary, build every selected model, "
                             "then exit 0 without running");
    }
    common.add_options()("help", "print this help and exit (also -h)")(
        "version", "print the version and exit");
    return common;
}

} // namespace

std::string CommandLine::usage() const
{
    std::ostringstream out;
    out << program_ << " " << projectVersion() << ": " << purpose_ << "\n\n"
        << "Usage: " << program_ << " [options]\n"
        << "Options take one dash, e.g. -case tutorials/bar1D/dykaBar (two dashes work too).\n\n"
        << commonOptions(withListTypes_, withDryRun_, withSet_);
    if (!extra_.options().empty())
    {
        out << "\n" << extra_;
    }
    // Boost prints every option with two dashes; show one, as options are meant to be typed
    // (the same width, so the descriptions stay aligned).
    std::string text = out.str();
    for (std::size_t at = text.find("\n  --"); at != std::string::npos;
         at = text.find("\n  --", at + 1))
    {
        text.replace(at, 5, "\n   -");
    }
    return text;
}

bool CommandLine::parse(int argc, const char* const* argv)
{
    // The invocation as the user would type it: the program's name, not the path it was
    // started by, so columns in messages do not depend on where the build lives.
    invocation_ = program_;
    std::vector<int> columns{1}; // 1-based column of each argument in the invocation line
    for (int i = 1; i < argc; ++i)
    {
        invocation_ += ' ';
        columns.push_back(static_cast<int>(invocation_.size()) + 1);
        invocation_ += argv[i];
    }
    std::string& quoted = commandLineOfProcess();
    quoted = program_;
    for (int i = 1; i < argc; ++i)
    {
        quoted += ' ' + shellQuoted(argv[i]);
    }
    auto source = std::make_shared<const SourceText>("command line", invocation_);
    const auto at = [&](int i) {
        return SourceLocation{source, 1, columns[static_cast<std::size_t>(i)],
                              static_cast<int>(std::string(argv[i]).size())};
    };
    // The argument equal to `text` (or `text=value`), from argument `from` on.
    const auto locate = [&](const std::string& text, int from = 1) {
        for (int i = from; i < argc; ++i)
        {
            const std::string arg = argv[i];
            if (arg == text || arg.rfind(text + "=", 0) == 0)
            {
                return at(i);
            }
        }
        return SourceLocation{source, 1, 1, 1};
    };
    // An option as typed: -name or --name.
    const auto locateOption = [&](std::string name) {
        while (!name.empty() && name.front() == '-')
        {
            name.erase(0, 1);
        }
        const SourceLocation single = locate("-" + name);
        return single.column > 1 ? single : locate("--" + name);
    };
    // The value of an option: the argument after -name, or the whole -name=value.
    const auto locateValue = [&](std::string name) {
        while (!name.empty() && name.front() == '-')
        {
            name.erase(0, 1);
        }
        for (int i = 1; i < argc; ++i)
        {
            const std::string arg = argv[i];
            if ((arg == "-" + name || arg == "--" + name) && i + 1 < argc)
            {
                return at(i + 1);
            }
            if (arg.rfind("-" + name + "=", 0) == 0 || arg.rfind("--" + name + "=", 0) == 0)
            {
                return at(i);
            }
        }
        return SourceLocation{source, 1, 1, 1};
    };

    po::options_description all;
    all.add(commonOptions(withListTypes_, withDryRun_, withSet_)).add(extra_);
    po::options_description hidden;
    hidden.add_options()("positional", po::value<std::vector<std::string>>());
    hidden.add_options()("h", "-help"); // -h as -help, as users try it first
    po::options_description parsing;
    parsing.add(all).add(hidden);
    po::positional_options_description positional;
    positional.add("positional", -1);

    const int style = (po::command_line_style::unix_style | po::command_line_style::allow_long_disguise) &
                      ~po::command_line_style::allow_guessing;
    try
    {
        po::store(po::command_line_parser(argc, argv)
                      .options(parsing)
                      .positional(positional)
                      .style(style)
                      .run(),
                  values_);
        po::notify(values_);
    }
    catch (const po::unknown_option& error)
    {
        std::vector<std::string> names;
        for (const auto& option : all.options())
        {
            names.push_back(option->long_name());
        }
        std::string name = error.get_option_name();
        while (!name.empty() && name.front() == '-')
        {
            name.erase(0, 1);
        }
        std::vector<std::string> notes{"Run '" + program_ + " -help' for the options."};
        if (const auto match = closestMatch(name, names))
        {
            notes.insert(notes.begin(), "Did you mean '-" + *match + "'?");
        }
        throw InputError(locateOption(error.get_option_name()), "unknown option '-" + name + "'",
                         notes);
    }
    catch (const po::error_with_option_name& error)
    {
        // e.g. "-threads two": point at the value given to the option.
        std::string name = error.get_option_name();
        const SourceLocation where = locateValue(name);
        while (!name.empty() && name.front() == '-')
        {
            name.erase(0, 1);
        }
        std::string message = error.what();
        for (std::string::size_type pos; (pos = message.find("--" + name)) != std::string::npos;)
        {
            message.replace(pos, name.size() + 2, "-" + name);
        }
        throw InputError(where, message, {"Run '" + program_ + " -help' for the options."});
    }
    catch (const po::error& error)
    {
        throw InputError(SourceLocation{source, 1, 1, 1}, error.what(),
                         {"Run '" + program_ + " -help' for the options."});
    }

    if (values_.count("help") || values_.count("h"))
    {
        std::cout << usage();
        return false;
    }
    if (values_.count("version"))
    {
        std::cout << program_ << " " << projectVersion() << " (git " << gitRevision() << ")\n";
        return false;
    }
    if (values_.count("case"))
    {
        caseDir_ = values_["case"].as<std::string>();
    }
    if (values_.count("set"))
    {
        sets_ = values_["set"].as<std::vector<std::string>>();
    }
    listTypes_ = values_.count("listTypes") > 0;
    dryRun_ = values_.count("dryRun") > 0;
    if (values_.count("positional"))
    {
        // Positional words in the order typed: find the argument that is each one.
        const auto& words = values_["positional"].as<std::vector<std::string>>();
        std::vector<SourceLocation> places;
        int from = 1;
        for (const auto& word : words)
        {
            for (int i = from; i < argc; ++i)
            {
                if (argv[i] == word)
                {
                    places.push_back(at(i));
                    from = i + 1;
                    break;
                }
            }
        }
        if (listTypes_ && words.size() == 1)
        {
            listFamily_ = words.front();
            listFamilyLocation_ = places.empty() ? SourceLocation{} : places.front();
        }
        else
        {
            const std::size_t index = listTypes_ ? 1 : 0;
            const std::string& first = words[index];
            throw InputError(index < places.size() ? places[index] : SourceLocation{source, 1, 1, 1},
                             "unexpected argument '" + first + "'",
                             {"Options start with '-' (e.g. -case DIR); -listTypes takes at most "
                              "one family name.",
                              "Run '" + program_ + " -help' for the options."});
        }
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(caseDir_, ec) && !listTypes_)
    {
        const bool exists = std::filesystem::exists(caseDir_, ec);
        throw InputError(locateValue("case"),
                         "the case folder '" + caseDir_.string() +
                             (exists ? "' is a file, not a folder" : "' does not exist"),
                         {"Give an existing folder with -case DIR (a case holds system/ and "
                          "constant/)."});
    }
    return true;
}

} // namespace sph
