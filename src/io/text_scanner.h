//! A tokenizer for the text mesh formats (OBJ, OFF, ASCII PLY and STL): walks
//! a file's bytes token by token, either within the current line or across
//! lines, skipping `#` comments if asked and joining backslash-continued lines
//! if asked. Numbers are parsed exactly (std::from_chars). Every failure is
//! Error(FABVDB_ERR_BAD_INPUT) naming the file, the line and the defect.
//! Reports progress (fraction of bytes consumed) as lines go by.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/progress.h"

namespace fabvdb::io {

struct TextSyntax {
    bool hash_comments = false;       //!< `#` starts a comment running to the end of the line
    bool line_continuation = false;   //!< a backslash at the end of a line joins the next line
};

class TextScanner {
public:
    //! `text` must outlive the scanner; `path` names the file in messages.
    TextScanner(std::string_view text, std::string path, TextSyntax syntax, Progress& progress);

    //! The next token of the current line; false (and nothing consumed) at
    //! the end of the line, a comment, or the end of the text.
    bool token_in_line(std::string_view& token);
    //! The next token, moving on to later lines as needed; false at the end.
    bool next_token(std::string_view& token);
    //! Discards the rest of the current line and moves to the next one.
    void next_line();
    //! Skips blank and comment-only lines; false if the text ends first.
    bool skip_blank_lines();
    bool at_end() const { return pos_ >= text_.size(); }
    size_t position() const { return pos_; }
    size_t line() const { return line_; }

    //! The next token (across lines) that must exist; `what` names it in the error.
    std::string_view expect_token(const char* what);
    //! The next token of this line that must exist.
    std::string_view expect_token_in_line(const char* what);

    double parse_double(std::string_view token, const char* what) const;
    int64_t parse_integer(std::string_view token, const char* what) const;

    //! Throws Error(BAD_INPUT) "<path>: line N: <defect>".
    [[noreturn]] void fail(const std::string& defect) const;

private:
    void skip_spaces_in_line();

    std::string_view text_;
    std::string path_;
    TextSyntax syntax_;
    Progress& progress_;
    size_t pos_ = 0;
    size_t line_ = 1;
};

}  // namespace fabvdb::io
