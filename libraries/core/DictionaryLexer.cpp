#include "DictionaryLexer.hpp"

#include "InputError.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace sph
{

namespace
{

bool isDelimiter(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) || c == '{' || c == '}' || c == '(' ||
           c == ')' || c == ';' || c == '"';
}

// A word is a number when the whole of it reads as one (decimal only: no hex, inf or nan) and
// is finite (1e999 overflows to inf: a word, which no real-valued key accepts).
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
    return end == text.c_str() + text.size() && std::isfinite(value);
}

} // namespace

const Token& Lexer::peek()
{
    if (!peeked_)
    {
        next_ = scan();
        peeked_ = true;
    }
    return next_;
}

Token Lexer::take()
{
    peek();
    peeked_ = false;
    return next_;
}

SourceLocation Lexer::at(int line, int column, int length) const
{
    return SourceLocation{source_, line, column, length};
}

void Lexer::advance()
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

void Lexer::skipSpaceAndComments()
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

Token Lexer::scan()
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

Token Lexer::scanString(Token& token)
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

Token Lexer::scanWord(Token& token)
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

std::string describeToken(const Token& token)
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

} // namespace sph
