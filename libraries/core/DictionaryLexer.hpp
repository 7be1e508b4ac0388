#pragma once
// The tokenizer of the dictionary syntax (words, numbers, "strings", $variables, #directives,
// braces, parentheses, ';'), skipping // and /* */ comments and tracking line and column.
// Internal to sphCore: DictionaryParser is its only user.

#include "SourceLocation.hpp"

#include <memory>
#include <string>

namespace sph
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

// "the end of the file", "string \"abc\"", "'$name'", "'word'": a token in messages.
std::string describeToken(const Token& token);

class Lexer
{
public:
    Lexer(std::shared_ptr<const SourceText> source, std::string text, int line = 1, int column = 1,
          std::string endName = "")
        : source_(std::move(source)), text_(std::move(text)), line_(line), column_(column),
          endName_(std::move(endName))
    {
    }

    // The next token, without consuming it.
    const Token& peek();
    // The next token, consumed.
    Token take();

    const std::shared_ptr<const SourceText>& source() const { return source_; }

    // A location in this lexer's source.
    SourceLocation at(int line, int column, int length = 1) const;

private:
    char current() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
    char ahead() const { return pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0'; }
    bool atEnd() const { return pos_ >= text_.size(); }

    void advance(); // one character, counting lines and columns
    void skipSpaceAndComments();
    Token scan();
    Token scanString(Token& token);
    Token scanWord(Token& token);

    std::shared_ptr<const SourceText> source_;
    std::string text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    bool peeked_ = false;
    Token next_;
    std::string endName_;
};

} // namespace sph
