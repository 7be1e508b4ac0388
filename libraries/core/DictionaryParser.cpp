#include "DictionaryParser.hpp"

#include "InputError.hpp"
#include "Suggest.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sph
{

namespace
{

struct Token
{
    enum class Kind
    {
        Word,
        Number,
        String,
        Variable,  // $name
        Directive, // #include
        OpenBrace,
        CloseBrace,
        OpenParen,
        CloseParen,
        Semicolon,
        End
    };
    Kind kind = Kind::End;
    std::string text;
    double number = 0.0;
    SourceLocation where;
    int endLine = 0;   // line of the last character
    int endColumn = 0; // column just after the last character
};

bool isDelimiter(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) || c == '{' || c == '}' || c == '(' ||
           c == ')' || c == ';' || c == '"';
}

// A word is a number when the whole of it reads as one (decimal only: no hex, inf or nan).
bool readNumber(const std::string& text, double& value)
{
    const char first = text.front();
    if (!(std::isdigit(static_cast<unsigned char>(first)) || first == '-' || first == '+' ||
          first == '.'))
    {
        return false;
    }
    for (char c : text)
    {
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' ||
              c == 'e' || c == 'E'))
        {
            return false;
        }
    }
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

class Lexer
{
public:
    Lexer(std::shared_ptr<const SourceText> source, std::string text, int line = 1, int column = 1,
          std::string endName = "")
        : source_(std::move(source)), text_(std::move(text)), line_(line), column_(column),
          endName_(std::move(endName))
    {
    }

    const Token& peek()
    {
        if (!peeked_)
        {
            next_ = scan();
            peeked_ = true;
        }
        return next_;
    }

    Token take()
    {
        peek();
        peeked_ = false;
        return next_;
    }

    const std::shared_ptr<const SourceText>& source() const { return source_; }

    SourceLocation at(int line, int column, int length = 1) const
    {
        return SourceLocation{source_, line, column, length};
    }

private:
    char current() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
    char ahead() const { return pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0'; }
    bool atEnd() const { return pos_ >= text_.size(); }

    void advance()
    {
        if (current() == '\n')
        {
            ++line_;
            column_ = 1;
        }
        else
        {
            ++column_;
        }
        ++pos_;
    }

    void skipSpaceAndComments()
    {
        while (!atEnd())
        {
            if (std::isspace(static_cast<unsigned char>(current())))
            {
                advance();
            }
            else if (current() == '/' && ahead() == '/')
            {
                while (!atEnd() && current() != '\n')
                {
                    advance();
                }
            }
            else if (current() == '/' && ahead() == '*')
            {
                const int line = line_;
                const int column = column_;
                advance();
                advance();
                while (!atEnd() && !(current() == '*' && ahead() == '/'))
                {
                    advance();
                }
                if (atEnd())
                {
                    throw InputError(at(line, column, 2), "unterminated comment: '/*' has no '*/'",
                                     {"Close the comment with '*/'."});
                }
                advance();
                advance();
            }
            else
            {
                return;
            }
        }
    }

    Token scan()
    {
        skipSpaceAndComments();
        Token token;
        token.where = at(line_, column_);
        if (atEnd())
        {
            token.kind = Token::Kind::End;
            token.text = endName_; // how messages name the end ("" = the end of the file)
            token.endLine = line_;
            token.endColumn = column_;
            return token;
        }
        const char c = current();
        const auto single = [&](Token::Kind kind)
        {
            token.kind = kind;
            token.text = std::string(1, c);
            advance();
            token.endLine = token.where.line;
            token.endColumn = token.where.column + 1;
            return token;
        };
        switch (c)
        {
        case '{':
            return single(Token::Kind::OpenBrace);
        case '}':
            return single(Token::Kind::CloseBrace);
        case '(':
            return single(Token::Kind::OpenParen);
        case ')':
            return single(Token::Kind::CloseParen);
        case ';':
            return single(Token::Kind::Semicolon);
        case '"':
            return scanString(token);
        default:
            return scanWord(token);
        }
    }

    Token scanString(Token& token)
    {
        advance(); // opening quote
        std::string value;
        while (!atEnd() && current() != '"' && current() != '\n')
        {
            if (current() == '\\' && (ahead() == '"' || ahead() == '\\'))
            {
                advance();
            }
            value += current();
            advance();
        }
        if (current() != '"')
        {
            throw InputError(token.where, "unterminated string: the closing '\"' is missing",
                             {"Strings must open and close on the same line."});
        }
        advance();
        token.kind = Token::Kind::String;
        token.text = std::move(value);
        token.endLine = line_;
        token.endColumn = column_;
        token.where.length = column_ - token.where.column;
        return token;
    }

    Token scanWord(Token& token)
    {
        std::string word;
        while (!atEnd() && !isDelimiter(current()) &&
               !(current() == '/' && (ahead() == '/' || ahead() == '*')))
        {
            word += current();
            advance();
        }
        token.text = word;
        token.endLine = line_;
        token.endColumn = column_;
        token.where.length = static_cast<int>(word.size());
        if (word[0] == '$')
        {
            token.kind = Token::Kind::Variable;
            token.text = word.substr(1);
            if (token.text.empty())
            {
                throw InputError(token.where, "'$' must be followed by the name of an entry",
                                 {"Write $name to copy the value of an earlier entry 'name'."});
            }
        }
        else if (word[0] == '#')
        {
            token.kind = Token::Kind::Directive;
        }
        else if (readNumber(word, token.number))
        {
            token.kind = Token::Kind::Number;
        }
        else
        {
            token.kind = Token::Kind::Word;
        }
        return token;
    }

    std::shared_ptr<const SourceText> source_;
    std::string text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    bool peeked_ = false;
    Token next_;
    std::string endName_;
};

std::string describe(const Token& token)
{
    switch (token.kind)
    {
    case Token::Kind::End:
        return token.text.empty() ? "the end of the file" : token.text;
    case Token::Kind::String:
        return "string \"" + token.text + "\"";
    case Token::Kind::Variable:
        return "'$" + token.text + "'";
    default:
        return "'" + token.text + "'";
    }
}

std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
    {
        throw InputError("cannot open dictionary file '" + path.string() + "'",
                         {"Check that the file exists and is readable."});
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class Parser
{
public:
    Parser(std::filesystem::path path, std::vector<std::filesystem::path> includeStack,
           std::vector<std::string> includeNames = {})
        : path_(std::move(path)), includeStack_(std::move(includeStack)),
          includeNames_(std::move(includeNames))
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
                    throw InputError(open->where,
                                     "unterminated '{': the dictionary '" + dict.displayName() +
                                         "' opened here is never closed",
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
                throw InputError(token.where, "expected a key, found " + describe(token),
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
                throw InputError(lexer.at(last.endLine, last.endColumn),
                                 "missing ';' after the value of '" + key.text + "'",
                                 {"Every 'key value' entry ends with ';' (found " +
                                  describe(token) + " next)."});
            }
            if (token.kind == Token::Kind::Variable && items.empty())
            {
                // `key $name;` copies a whole dictionary too.
                const Token variable = lexer.take();
                const Entry& source = resolve(variable, dict);
                if (source.isDict() && lexer.peek().kind == Token::Kind::Semicolon)
                {
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
            throw InputError(key.where, "the entry '" + key.text + "' has no value",
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
                throw InputError(token.where, "'$" + token.text + "' cannot be used here",
                                 {"Variables are only available inside dictionary files."});
            }
            appendCopy(token, resolve(token, *scope), items);
            break;
        }
        case Token::Kind::OpenParen:
        {
            std::vector<Item> content;
            while (lexer.peek().kind != Token::Kind::CloseParen)
            {
                const Token& inner = lexer.peek();
                if (inner.kind == Token::Kind::End || inner.kind == Token::Kind::Semicolon ||
                    inner.kind == Token::Kind::OpenBrace || inner.kind == Token::Kind::CloseBrace)
                {
                    throw InputError(token.where,
                                     "unterminated '(': the list opened here has no ')'",
                                     {"Found " + describe(inner) + " before the closing ')'."});
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
            throw InputError(token.where, "unexpected " + describe(token) + " in a value",
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
            const std::string hint = didYouMean(variable.text, scope.visibleKeys());
            if (!hint.empty())
            {
                notes.push_back(hint);
            }
            throw InputError(variable.where, "undefined variable '$" + variable.text + "'", notes);
        }
        entry->markReferenced();
        return *entry;
    }

    void appendCopy(const Token& variable, const Entry& source, std::vector<Item>& items)
    {
        if (source.isDict())
        {
            throw InputError(variable.where,
                             "'$" + variable.text +
                                 "' is a dictionary and cannot be part of a value",
                             {"Copy a dictionary with 'key $" + variable.text +
                              ";' or merge it with '$" + variable.text + ";'."});
        }
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
                             "'$" + variable.text + ";' merges a dictionary, but '" +
                                 variable.text + "' is a value",
                             {"Use 'key $" + variable.text + ";' to copy a value."});
        }
        if (lexer.peek().kind != Token::Kind::Semicolon)
        {
            throw InputError(lexer.at(variable.endLine, variable.endColumn),
                             "missing ';' after '$" + variable.text + "'");
        }
        lexer.take();
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
            throw InputError(directive.where, "unknown directive '" + directive.text + "'",
                             {"The only directive is #include \"file\"."});
        }
        const Token file = lexer.take();
        if (file.kind != Token::Kind::String)
        {
            throw InputError(file.where,
                             "#include needs a quoted file name, found " + describe(file),
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
        if (!std::filesystem::is_regular_file(target))
        {
            throw InputError(file.where, "cannot open included file '" + file.text + "'",
                             {"Looked for " + target.string() +
                              " (an #include path is relative to the including file)."});
        }
        const std::string displayName =
            (std::filesystem::path(file.where.fileName()).parent_path() / file.text)
                .lexically_normal()
                .string();
        const std::string text = readFile(target);
        auto source = std::make_shared<const SourceText>(displayName, text);
        Lexer inner(source, text);
        auto stack = includeStack_;
        stack.push_back(canonical);
        auto names = includeNames_;
        names.push_back(displayName);
        Parser parser(target, stack, names);
        parser.parseBody(inner, dict, nullptr);
    }

    std::filesystem::path path_;
    std::vector<std::filesystem::path> includeStack_;
    std::vector<std::string> includeNames_; // display names of the same files
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
