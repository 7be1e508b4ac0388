#include "DictionaryParser.hpp"

#include "DictionaryLexer.hpp"
#include "InputError.hpp"
#include "Suggest.hpp"
#include "TextFile.hpp"

#include <map>

namespace sph
{

namespace
{

// Bounds that keep hostile input from exhausting the stack or the memory (issue 12 items 4
// and 5): no case needs more than a few levels of nesting or a few thousand copied values.
constexpr int maxNesting = 200;
constexpr std::size_t maxCopiedItems = 1000000;

// The items of a value, counting the contents of its lists.
std::size_t itemCount(const std::vector<Item>& items)
{
    std::size_t count = items.size();
    for (const Item& item : items)
    {
        if (item.isList())
        {
            count += itemCount(item.items());
        }
    }
    return count;
}

std::size_t itemCount(const Dictionary& dict)
{
    std::size_t count = 0;
    for (const Entry& entry : dict.entries())
    {
        count += 1 + (entry.isDict() ? itemCount(entry.dict()) : itemCount(entry.items()));
    }
    return count;
}

// The text of a dictionary file without a UTF-8 byte-order mark (some Windows editors write
// one; it would otherwise be part of the first key; columns then count from after it) and with
// every line ending as '\n': Windows' "\r\n" and old Mac OS's lone '\r' too, so that line
// numbers in messages are the ones an editor shows.
std::string readFile(const std::filesystem::path& path)
{
    std::string raw =
        readTextFile(path, "dictionary file", {"Check that the file exists and is readable."});
    const std::size_t start = raw.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
    std::string text;
    text.reserve(raw.size() - start);
    for (std::size_t i = start; i < raw.size(); ++i)
    {
        if (raw[i] != '\r')
        {
            text += raw[i];
        }
        else if (i + 1 == raw.size() || raw[i + 1] != '\n')
        {
            text += '\n';
        }
    }
    return text;
}

class Parser
{
public:
    // `included`: the file was named by an #include, which may name any file the user can read
    // (/etc/shadow, /proc/self/environ); its messages then quote nothing the quoted line does
    // not show (issue 12 item 2).
    Parser(std::filesystem::path path, std::vector<std::filesystem::path> includeStack,
           std::vector<std::string> includeNames = {}, bool included = false)
        : path_(std::move(path)), includeStack_(std::move(includeStack)),
          includeNames_(std::move(includeNames)), confined_(included)
    {
    }

    // Parses entries until the end of the lexer's input into `dict`.
    void parseFile(Lexer& lexer, Dictionary& dict)
    {
        parseBody(lexer, dict, nullptr);
        dict.setEndLocation(lexer.peek().where);
    }

    std::vector<Item> parseStandaloneValue(Lexer& lexer, const Dictionary* scope)
    {
        std::vector<Item> items;
        while (lexer.peek().kind != Token::Kind::End)
        {
            appendItem(lexer, items, scope);
        }
        return items;
    }

private:
    // One level of '{' or '(' while it is being read.
    class Nesting
    {
    public:
        Nesting(int& depth, const SourceLocation& where, const char* what) : depth_(depth)
        {
            if (depth_ >= maxNesting)
            {
                throw InputError(where,
                                 std::string(what) + " nested more than " +
                                     std::to_string(maxNesting) + " levels deep",
                                 {"A case needs a few levels; check for unbalanced brackets or "
                                  "generated input."});
            }
            ++depth_;
        }
        ~Nesting() { --depth_; }
        Nesting(const Nesting&) = delete;
        Nesting& operator=(const Nesting&) = delete;

    private:
        int& depth_;
    };

    // Counts what $name copies; a copy past the bound is an input error (ten lines each
    // copying the previous one ten times would otherwise grow without bound).
    void countCopy(const Token& variable, std::size_t items)
    {
        copied_ += items;
        if (copied_ > maxCopiedItems)
        {
            throw InputError(variable.where,
                             "'$" + shownName(variable) + "' makes the file expand to more than " +
                                 std::to_string(maxCopiedItems) + " copied values",
                             {"Variables that copy each other repeatedly grow exponentially; "
                              "copy the values you need once."});
        }
    }

    int depth_ = 0;
    std::size_t copied_ = 0;

    // A token as a message names it. In an included file only a short token on the line the
    // error quotes is shown; any other is named by its kind and line, never by its text.
    std::string describe(const Token& token, int errorLine) const
    {
        static const std::map<Token::Kind, const char*> textual = {
            {Token::Kind::Word, "a word"},
            {Token::Kind::Number, "a number"},
            {Token::Kind::String, "a string"},
            {Token::Kind::Variable, "a variable"},
            {Token::Kind::Directive, "a directive"}};
        const auto kind = textual.find(token.kind);
        if (!confined_ || kind == textual.end() || shows(token.text, token.where.line, errorLine))
        {
            return describeToken(token); // punctuation and the end show no file content
        }
        return std::string(kind->second) + " on line " + std::to_string(token.where.line);
    }

    // The name of an entry as a message quotes it ("'bar' "), or "" where describe() would not
    // show its text.
    std::string entryName(const std::string& key, int keyLine, int errorLine) const
    {
        return !confined_ || shows(key, keyLine, errorLine) ? "'" + key + "' " : "";
    }

    // A variable's name in a message: "..." for a long one in an included file.
    std::string shownName(const Token& variable) const
    {
        return !confined_ || shows(variable.text, 0, 0) ? variable.text : "...";
    }

    // Text the quoted line shows anyway: on that line and short enough for its window.
    static bool shows(const std::string& text, int line, int errorLine)
    {
        constexpr std::size_t longest = 40;
        return line == errorLine && text.size() <= longest;
    }

    // Entries up to a closing brace (when `open` is given) or the end of input.
    void parseBody(Lexer& lexer, Dictionary& dict, const Token* open)
    {
        while (true)
        {
            const Token& token = lexer.peek();
            switch (token.kind)
            {
            case Token::Kind::End:
                if (open)
                {
                    throw InputError(
                        open->where,
                        "unterminated '{': the dictionary " +
                            entryName(dict.displayName(), dict.location().line, open->where.line) +
                            "opened here is never closed",
                        {"Add the matching '}'."});
                }
                return;
            case Token::Kind::CloseBrace:
                if (!open)
                {
                    throw InputError(token.where, "unexpected '}': no dictionary is open here",
                                     {"Remove it, or check the braces above."});
                }
                dict.setEndLocation(token.where);
                lexer.take();
                return;
            case Token::Kind::Semicolon:
                lexer.take(); // a stray ';' (e.g. after '}') is harmless
                break;
            case Token::Kind::Directive:
                parseDirective(lexer, dict);
                break;
            case Token::Kind::Variable:
                parseMerge(lexer, dict);
                break;
            case Token::Kind::Word:
                parseEntry(lexer, dict);
                break;
            default:
                throw InputError(token.where,
                                 "expected a key, found " + describe(token, token.where.line),
                                 {"An entry is 'key value;' or 'name { ... }'."});
            }
        }
    }

    void parseEntry(Lexer& lexer, Dictionary& dict)
    {
        const Token key = lexer.take();
        const Token& next = lexer.peek();
        if (next.kind == Token::Kind::OpenBrace)
        {
            const Token open = lexer.take();
            const Nesting level(depth_, open.where, "dictionaries");
            auto child = std::make_unique<Dictionary>("", key.where);
            child->reparent(&dict, key.text); // so $name inside can see enclosing scopes
            parseBody(lexer, *child, &open);
            dict.add(Entry(key.text, key.where, std::move(child)));
            return;
        }
        std::vector<Item> items;
        const Token* previous = &key;
        Token last = key;
        while (true)
        {
            const Token& token = lexer.peek();
            if (token.kind == Token::Kind::Semicolon)
            {
                lexer.take();
                break;
            }
            if (token.kind == Token::Kind::End || token.kind == Token::Kind::CloseBrace ||
                token.kind == Token::Kind::OpenBrace ||
                (previous != &key && token.where.line > last.endLine))
            {
                // A value never continues on a new line outside parentheses, so a token on the
                // next line means the ';' was forgotten.
                const std::string name = entryName(key.text, key.where.line, last.endLine);
                throw InputError(lexer.at(last.endLine, last.endColumn),
                                 name.empty() ? "missing ';' after this value"
                                              : "missing ';' after the value of " +
                                                    name.substr(0, name.size() - 1),
                                 {"Every 'key value' entry ends with ';' (found " +
                                  describe(token, last.endLine) + " next)."});
            }
            if (token.kind == Token::Kind::Variable && items.empty())
            {
                // `key $name;` copies a whole dictionary too.
                const Token variable = lexer.take();
                const Entry& source = resolve(variable, dict);
                if (source.isDict() && lexer.peek().kind == Token::Kind::Semicolon)
                {
                    countCopy(variable, itemCount(source.dict()));
                    lexer.take();
                    auto copy = std::make_unique<Dictionary>(source.dict());
                    dict.add(Entry(key.text, key.where, std::move(copy)));
                    return;
                }
                appendCopy(variable, source, items);
                last = variable;
                previous = &last;
                continue;
            }
            last = token;
            appendItem(lexer, items, &dict, &last);
            previous = &last;
        }
        if (items.empty())
        {
            throw InputError(key.where,
                             "the entry " + entryName(key.text, key.where.line, key.where.line) +
                                 "has no value",
                             {"Write 'key value;' (or 'key { ... }' for a dictionary)."});
        }
        dict.add(Entry(key.text, key.where, std::move(items)));
    }

    // Appends one item (word, number, string, list or $copy); `last` receives the last token
    // consumed, so that a missing ';' can be reported right after it.
    void appendItem(Lexer& lexer, std::vector<Item>& items, const Dictionary* scope,
                    Token* last = nullptr)
    {
        Token token = lexer.take();
        switch (token.kind)
        {
        case Token::Kind::Word:
            items.push_back(Item::word(token.text, token.where));
            break;
        case Token::Kind::Number:
            items.push_back(Item::number(token.text, token.number, token.where));
            break;
        case Token::Kind::String:
            items.push_back(Item::string(token.text, token.where));
            break;
        case Token::Kind::Variable:
        {
            if (!scope)
            {
                throw InputError(token.where, "'$" + shownName(token) + "' cannot be used here",
                                 {"Variables are only available inside dictionary files."});
            }
            appendCopy(token, resolve(token, *scope), items);
            break;
        }
        case Token::Kind::OpenParen:
        {
            const Nesting level(depth_, token.where, "lists");
            std::vector<Item> content;
            while (lexer.peek().kind != Token::Kind::CloseParen)
            {
                const Token& inner = lexer.peek();
                if (inner.kind == Token::Kind::End || inner.kind == Token::Kind::Semicolon ||
                    inner.kind == Token::Kind::OpenBrace || inner.kind == Token::Kind::CloseBrace)
                {
                    throw InputError(token.where,
                                     "unterminated '(': the list opened here has no ')'",
                                     {"Found " + describe(inner, token.where.line) +
                                      " before the closing ')'."});
                }
                appendItem(lexer, content, scope);
            }
            const Token close = lexer.take();
            SourceLocation where = token.where;
            if (close.where.line == token.where.line)
            {
                where.length = close.where.column - token.where.column + 1;
            }
            items.push_back(Item::list(std::move(content), where));
            token = close;
            break;
        }
        default:
            throw InputError(token.where,
                             "unexpected " + describe(token, token.where.line) + " in a value",
                             {"A value is made of words, numbers, \"strings\" and (lists)."});
        }
        if (last)
        {
            *last = token;
        }
    }

    const Entry& resolve(const Token& variable, const Dictionary& scope)
    {
        const Entry* entry = scope.lookupScoped(variable.text);
        if (!entry)
        {
            std::vector<std::string> notes{"A variable copies an entry defined earlier in this "
                                           "dictionary or an enclosing one."};
            // The suggestion would quote another entry's key: not from an included file.
            const std::string hint =
                confined_ ? std::string() : didYouMean(variable.text, scope.visibleKeys());
            if (!hint.empty())
            {
                notes.push_back(hint);
            }
            throw InputError(variable.where, "undefined variable '$" + shownName(variable) + "'",
                             notes);
        }
        entry->markReferenced();
        return *entry;
    }

    void appendCopy(const Token& variable, const Entry& source, std::vector<Item>& items)
    {
        if (source.isDict())
        {
            throw InputError(variable.where,
                             "'$" + shownName(variable) +
                                 "' is a dictionary and cannot be part of a value",
                             {"Copy a dictionary with 'key $" + shownName(variable) +
                              ";' or merge it with '$" + shownName(variable) + ";'."});
        }
        countCopy(variable, itemCount(source.items()));
        items.insert(items.end(), source.items().begin(), source.items().end());
    }

    // `$name;` as a statement: merge the entries of dictionary `name`.
    void parseMerge(Lexer& lexer, Dictionary& dict)
    {
        const Token variable = lexer.take();
        const Entry& source = resolve(variable, dict);
        if (!source.isDict())
        {
            throw InputError(variable.where,
                             "'$" + shownName(variable) + ";' merges a dictionary, but '" +
                                 shownName(variable) + "' is a value",
                             {"Use 'key $" + shownName(variable) + ";' to copy a value."});
        }
        if (lexer.peek().kind != Token::Kind::Semicolon)
        {
            throw InputError(lexer.at(variable.endLine, variable.endColumn),
                             "missing ';' after '$" + shownName(variable) + "'");
        }
        lexer.take();
        countCopy(variable, itemCount(source.dict()));
        const Dictionary copy(source.dict());
        for (const Entry& entry : copy.entries())
        {
            Entry merged(entry);
            merged.setOverridable(true);
            dict.add(std::move(merged));
        }
    }

    void parseDirective(Lexer& lexer, Dictionary& dict)
    {
        const Token directive = lexer.take();
        if (directive.text != "#include")
        {
            throw InputError(directive.where,
                             "unknown directive " + describe(directive, directive.where.line),
                             {"The only directive is #include \"file\"."});
        }
        const Token file = lexer.take();
        if (file.kind != Token::Kind::String)
        {
            throw InputError(file.where,
                             "#include needs a quoted file name, found " +
                                 describe(file, file.where.line),
                             {"Write #include \"fileName\" (relative to this file)."});
        }
        const std::filesystem::path here = path_.parent_path();
        const std::filesystem::path target = (here / file.text).lexically_normal();
        std::error_code ec;
        const std::filesystem::path canonical = std::filesystem::weakly_canonical(target, ec);
        for (const auto& open : includeStack_)
        {
            if (open == canonical)
            {
                std::string chain;
                for (const auto& step : includeNames_)
                {
                    chain += step + " -> ";
                }
                const std::string target =
                    (std::filesystem::path(file.where.fileName()).parent_path() / file.text)
                        .lexically_normal()
                        .string();
                throw InputError(file.where,
                                 "#include cycle: '" + file.text + "' is already being read",
                                 {"Include chain: " + chain + target});
            }
        }
        if (const std::string reason = unreadableReason(target); !reason.empty())
        {
            throw InputError(file.where, "cannot open included file '" + file.text + "': " + reason,
                             {"Looked for " + target.string() +
                              " (an #include path is relative to the including file)."});
        }
        const std::string displayName =
            (std::filesystem::path(file.where.fileName()).parent_path() / file.text)
                .lexically_normal()
                .string();
        std::string text;
        try
        {
            text = readFile(target);
        }
        catch (const InputError& unreadable) // a read error (/proc/self/mem): at the #include
        {
            throw InputError(file.where, unreadable.message(), unreadable.notes());
        }
        // Messages about the included file say where it was included from (and from where
        // that file was, for nested includes).
        std::vector<std::string> includedFrom{file.where.prefix()};
        const std::vector<std::string>& outer = file.where.source->includedFrom();
        includedFrom.insert(includedFrom.end(), outer.begin(), outer.end());
        auto source = std::make_shared<const SourceText>(displayName, text, std::move(includedFrom));
        Lexer inner(source, text);
        auto stack = includeStack_;
        stack.push_back(canonical);
        auto names = includeNames_;
        names.push_back(displayName);
        Parser parser(target, stack, names, true);
        parser.parseBody(inner, dict, nullptr);
    }

    std::filesystem::path path_;
    std::vector<std::filesystem::path> includeStack_;
    std::vector<std::string> includeNames_; // display names of the same files
    bool confined_;                         // an included file: see the constructor
};

} // namespace

std::unique_ptr<Dictionary> DictionaryParser::parseFile(const std::filesystem::path& path,
                                                        const std::string& displayName)
{
    const std::string text = readFile(path);
    auto source = std::make_shared<const SourceText>(displayName, text);
    Lexer lexer(source, text);
    auto dict = std::make_unique<Dictionary>("", SourceLocation{source, 0, 0, 1});
    std::error_code ec;
    Parser parser(path, {std::filesystem::weakly_canonical(path, ec)}, {displayName});
    parser.parseFile(lexer, *dict);
    return dict;
}

std::unique_ptr<Dictionary> DictionaryParser::parseString(const std::string& text,
                                                          const std::string& displayName)
{
    auto source = std::make_shared<const SourceText>(displayName, text);
    Lexer lexer(source, text);
    auto dict = std::make_unique<Dictionary>("", SourceLocation{source, 0, 0, 1});
    Parser parser(std::filesystem::current_path() / displayName, {});
    parser.parseFile(lexer, *dict);
    return dict;
}

std::vector<Item> DictionaryParser::parseValue(const std::shared_ptr<const SourceText>& source,
                                               const std::string& text, int firstColumn)
{
    Lexer lexer(source, text, 1, firstColumn, "the end of the value");
    Parser parser(std::filesystem::current_path(), {});
    std::vector<Item> items = parser.parseStandaloneValue(lexer, nullptr);
    if (items.empty())
    {
        throw InputError(SourceLocation{source, 1, firstColumn, 1}, "empty value in -set",
                         {"Write -set path.to.key=value."});
    }
    return items;
}

std::unique_ptr<Dictionary>
DictionaryParser::parseDictionaryValue(const std::shared_ptr<const SourceText>& source,
                                       const std::string& text, int firstColumn,
                                       const std::string& name)
{
    Lexer lexer(source, text, 1, firstColumn, "the closing '}'");
    auto dict = std::make_unique<Dictionary>(name, SourceLocation{source, 1, firstColumn, 1});
    Parser parser(std::filesystem::current_path(), {});
    parser.parseFile(lexer, *dict);
    return dict;
}

} // namespace sph
