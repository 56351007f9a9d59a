//! TextScanner: byte-level scanning with explicit line tracking.
#include "io/text_scanner.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace fabvdb::io {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

constexpr size_t progress_every_lines = 4096;

//! The token without a leading '+' (which from_chars does not take); empty
//! (so not a number) when another sign follows it.
std::string_view without_plus(std::string_view token) {
    if (token.empty() || token.front() != '+') return token;
    token.remove_prefix(1);
    if (!token.empty() && (token.front() == '-' || token.front() == '+')) return {};
    return token;
}

}  // namespace

TextScanner::TextScanner(std::string_view text, std::string path, TextSyntax syntax, Progress& progress)
    : text_(text), path_(std::move(path)), syntax_(syntax), progress_(progress) {}

void TextScanner::skip_spaces_in_line() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (is_space(c)) {
            ++pos_;
        } else if (c == '\\' && syntax_.line_continuation) {
            size_t after = pos_ + 1;
            while (after < text_.size() && is_space(text_[after])) ++after;
            if (after < text_.size() && text_[after] != '\n') return;  // a backslash inside the line
            pos_ = after < text_.size() ? after + 1 : after;
            ++line_;
        } else {
            return;
        }
    }
}

bool TextScanner::token_in_line(std::string_view& token) {
    skip_spaces_in_line();
    if (pos_ >= text_.size() || text_[pos_] == '\n') return false;
    if (syntax_.hash_comments && text_[pos_] == '#') return false;
    const size_t start = pos_;
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (is_space(c) || c == '\n' || (syntax_.hash_comments && c == '#')) break;
        if (c == '\\' && syntax_.line_continuation) {
            size_t after = pos_ + 1;
            while (after < text_.size() && is_space(text_[after])) ++after;
            if (after >= text_.size() || text_[after] == '\n') break;
        }
        ++pos_;
    }
    token = text_.substr(start, pos_ - start);
    return true;
}

void TextScanner::next_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') {
        if (syntax_.line_continuation && text_[pos_] == '\\') {
            const size_t before = pos_;
            skip_spaces_in_line();  // steps over a continuation, if this is one
            if (pos_ == before) ++pos_;
            continue;
        }
        ++pos_;
    }
    if (pos_ < text_.size()) ++pos_;
    if (++line_ % progress_every_lines == 0) progress_.update(static_cast<double>(pos_) / text_.size());
}

bool TextScanner::skip_blank_lines() {
    while (pos_ < text_.size()) {
        skip_spaces_in_line();
        if (pos_ >= text_.size()) return false;
        const char c = text_[pos_];
        if (c == '\n' || (syntax_.hash_comments && c == '#')) {
            next_line();
            continue;
        }
        return true;
    }
    return false;
}

bool TextScanner::next_token(std::string_view& token) {
    while (true) {
        if (token_in_line(token)) return true;
        if (at_end()) return false;
        next_line();
    }
}

std::string_view TextScanner::expect_token(const char* what) {
    std::string_view token;
    if (!next_token(token)) fail(std::string("file ends where ") + what + " was expected");
    return token;
}

std::string_view TextScanner::expect_token_in_line(const char* what) {
    std::string_view token;
    if (!token_in_line(token)) fail(std::string("line ends where ") + what + " was expected");
    return token;
}

double TextScanner::parse_double(std::string_view token, const char* what) const {
    const std::string_view digits = without_plus(token);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range && end == digits.data() + digits.size()) {
        // from_chars reports underflow too; a value too small for a double is (close to) zero.
        const double rounded = std::strtod(std::string(digits).c_str(), nullptr);
        if (!std::isfinite(rounded))
            fail(std::string(what) + " '" + std::string(token.substr(0, 40)) + "' is out of range");
        return rounded;
    }
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        fail(std::string(what) + " is not a number: '" + std::string(token.substr(0, 40)) + "'");
    return value;
}

int64_t TextScanner::parse_integer(std::string_view token, const char* what) const {
    const std::string_view digits = without_plus(token);
    int64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
        fail(std::string(what) + " '" + std::string(token.substr(0, 40)) + "' is out of range");
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        fail(std::string(what) + " is not an integer: '" + std::string(token.substr(0, 40)) + "'");
    return value;
}

void TextScanner::fail(const std::string& defect) const {
    throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": line " + std::to_string(line_) + ": " + defect);
}

}  // namespace fabvdb::io
