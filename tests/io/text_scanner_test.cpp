// The text formats' tokenizer: tokens within a line and across lines, line
// counting, `#` comments and backslash continuations only when asked, exact
// number parsing, Error(BAD_INPUT) "<file>: line N: ..." on every defect, and
// progress reports (and cancellation) as lines go by.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/text_scanner.h"

namespace {

using fabvdb::io::TextScanner;
using fabvdb::io::TextSyntax;

std::vector<std::string> line_tokens(TextScanner& scanner) {
    std::vector<std::string> tokens;
    std::string_view token;
    while (scanner.token_in_line(token)) tokens.emplace_back(token);
    return tokens;
}

std::vector<std::string> all_tokens(TextScanner& scanner) {
    std::vector<std::string> tokens;
    std::string_view token;
    while (scanner.next_token(token)) tokens.emplace_back(token);
    return tokens;
}

using Tokens = std::vector<std::string>;

// Runs `call`, which must throw Error(BAD_INPUT); returns its message.
template <typename Call>
std::string bad_input_message(Call call) {
    try {
        call();
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_BAD_INPUT);
        return error.what();
    }
    ADD_FAILURE() << "no error";
    return "";
}

TEST(TextScanner, TokensWithinLinesAndLineNumbers) {
    fabvdb::Progress progress;
    TextScanner scanner("v 1.5\t-2  3\r\nf 1 2 3\n\nlast", "m.obj", TextSyntax{}, progress);
    EXPECT_EQ(scanner.line(), 1u);
    EXPECT_EQ(line_tokens(scanner), (Tokens{"v", "1.5", "-2", "3"}));
    // At the end of the line nothing more is consumed.
    const size_t at = scanner.position();
    std::string_view token;
    EXPECT_FALSE(scanner.token_in_line(token));
    EXPECT_EQ(scanner.position(), at);
    scanner.next_line();
    EXPECT_EQ(scanner.line(), 2u);
    EXPECT_EQ(line_tokens(scanner), (Tokens{"f", "1", "2", "3"}));
    scanner.next_line();
    EXPECT_EQ(line_tokens(scanner), Tokens{});
    scanner.next_line();
    EXPECT_EQ(scanner.line(), 4u);
    EXPECT_EQ(line_tokens(scanner), (Tokens{"last"}));
    EXPECT_TRUE(scanner.at_end());
    EXPECT_FALSE(scanner.next_token(token));
}

TEST(TextScanner, NextLineDiscardsTheRestOfTheLine) {
    fabvdb::Progress progress;
    TextScanner scanner("a b c\nd", "x", TextSyntax{}, progress);
    std::string_view token;
    ASSERT_TRUE(scanner.token_in_line(token));
    EXPECT_EQ(token, "a");
    scanner.next_line();
    EXPECT_EQ(line_tokens(scanner), (Tokens{"d"}));
}

TEST(TextScanner, NextTokenCrossesLines) {
    fabvdb::Progress progress;
    TextScanner scanner("ply\n\n  format ascii 1.0  \n end", "p.ply", TextSyntax{}, progress);
    EXPECT_EQ(all_tokens(scanner), (Tokens{"ply", "format", "ascii", "1.0", "end"}));
    EXPECT_EQ(scanner.line(), 4u);
    EXPECT_TRUE(scanner.at_end());
}

TEST(TextScanner, EmptyTextHasNoTokens) {
    fabvdb::Progress progress;
    TextScanner scanner("", "empty.off", TextSyntax{true, true}, progress);
    EXPECT_TRUE(scanner.at_end());
    std::string_view token;
    EXPECT_FALSE(scanner.token_in_line(token));
    EXPECT_FALSE(scanner.next_token(token));
    EXPECT_FALSE(scanner.skip_blank_lines());
}

TEST(TextScanner, HashCommentsOnlyWhenAsked) {
    const std::string_view text = "a b# c d\ne # f\n";
    {
        fabvdb::Progress progress;
        TextScanner scanner(text, "x", TextSyntax{true, false}, progress);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"a", "b"}));
        scanner.next_line();
        EXPECT_EQ(line_tokens(scanner), (Tokens{"e"}));
    }
    {
        fabvdb::Progress progress;
        TextScanner scanner(text, "x", TextSyntax{true, false}, progress);
        EXPECT_EQ(all_tokens(scanner), (Tokens{"a", "b", "e"}));
    }
    {
        fabvdb::Progress progress;
        TextScanner scanner(text, "x", TextSyntax{false, false}, progress);
        EXPECT_EQ(all_tokens(scanner), (Tokens{"a", "b#", "c", "d", "e", "#", "f"}));
    }
}

TEST(TextScanner, BackslashContinuationOnlyWhenAsked) {
    // The backslash ends the line (spaces may follow it); a backslash inside
    // a line is part of a token.
    const std::string_view text = "f 1 2 \\\n 3 \\  \n4\nf a\\b 5\n";
    {
        fabvdb::Progress progress;
        TextScanner scanner(text, "x", TextSyntax{false, true}, progress);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"f", "1", "2", "3", "4"}));
        EXPECT_EQ(scanner.line(), 3u);
        scanner.next_line();
        EXPECT_EQ(scanner.line(), 4u);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"f", "a\\b", "5"}));
    }
    {
        fabvdb::Progress progress;
        TextScanner scanner(text, "x", TextSyntax{false, false}, progress);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"f", "1", "2", "\\"}));
        scanner.next_line();
        EXPECT_EQ(scanner.line(), 2u);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"3", "\\"}));
    }
}

TEST(TextScanner, NextLineStepsOverAContinuedLine) {
    fabvdb::Progress progress;
    TextScanner scanner("a \\\nb c\nd", "x", TextSyntax{false, true}, progress);
    std::string_view token;
    ASSERT_TRUE(scanner.token_in_line(token));
    scanner.next_line();  // discards "b c" too: it belongs to the same logical line
    EXPECT_EQ(scanner.line(), 3u);
    EXPECT_EQ(line_tokens(scanner), (Tokens{"d"}));
}

TEST(TextScanner, SkipBlankLines) {
    {
        fabvdb::Progress progress;
        TextScanner scanner("\n   \n# comment\n\t x y\n", "x", TextSyntax{true, false}, progress);
        EXPECT_TRUE(scanner.skip_blank_lines());
        EXPECT_EQ(scanner.line(), 4u);
        EXPECT_EQ(line_tokens(scanner), (Tokens{"x", "y"}));
    }
    {
        fabvdb::Progress progress;
        TextScanner scanner("\n  \n# only comments\n#\n", "x", TextSyntax{true, false}, progress);
        EXPECT_FALSE(scanner.skip_blank_lines());
    }
    {
        // Without comment syntax a '#' line is not blank.
        fabvdb::Progress progress;
        TextScanner scanner("\n# not a comment\n", "x", TextSyntax{}, progress);
        EXPECT_TRUE(scanner.skip_blank_lines());
        EXPECT_EQ(scanner.line(), 2u);
    }
}

TEST(TextScanner, ExpectTokenFailsNamingFileLineAndWhat) {
    fabvdb::Progress progress;
    TextScanner scanner("OFF\n3 1 0\n", "cube.off", TextSyntax{true, false}, progress);
    EXPECT_EQ(scanner.expect_token("the header"), "OFF");
    EXPECT_EQ(scanner.expect_token("the vertex count"), "3");
    EXPECT_EQ(scanner.expect_token_in_line("the face count"), "1");
    EXPECT_EQ(scanner.expect_token_in_line("the edge count"), "0");
    const std::string in_line = bad_input_message([&] { scanner.expect_token_in_line("a vertex"); });
    EXPECT_EQ(in_line.rfind("cube.off: line 2: ", 0), 0u) << in_line;
    EXPECT_NE(in_line.find("a vertex"), std::string::npos) << in_line;
    const std::string at_end = bad_input_message([&] { scanner.expect_token("the first vertex"); });
    EXPECT_EQ(at_end.rfind("cube.off: line 3: ", 0), 0u) << at_end;
    EXPECT_NE(at_end.find("the first vertex"), std::string::npos) << at_end;
}

TEST(TextScanner, ParsesDoublesExactly) {
    fabvdb::Progress progress;
    TextScanner scanner("", "n.obj", TextSyntax{}, progress);
    EXPECT_EQ(scanner.parse_double("0.1", "x"), 0.1);
    EXPECT_EQ(scanner.parse_double("+2", "x"), 2.0);
    EXPECT_EQ(scanner.parse_double("-3.25e-2", "x"), -0.0325);
    EXPECT_EQ(scanner.parse_double("1.7976931348623157e308", "x"), std::numeric_limits<double>::max());
    EXPECT_EQ(scanner.parse_double("4.9406564584124654e-324", "x"), std::numeric_limits<double>::denorm_min());
    // Too small for a double: (close to) zero, not an error.
    EXPECT_LE(std::abs(scanner.parse_double("1e-400", "x")), std::numeric_limits<double>::denorm_min());
    for (const char* bad : {"", "+", "abc", "1.5x", "1,5", "--1"}) {
        const std::string message = bad_input_message([&] { scanner.parse_double(bad, "a coordinate"); });
        EXPECT_EQ(message.rfind("n.obj: line 1: ", 0), 0u) << message;
        EXPECT_NE(message.find("a coordinate"), std::string::npos) << message;
    }
    bad_input_message([&] { scanner.parse_double("1e400", "a coordinate"); });
    bad_input_message([&] { scanner.parse_double("-1e400", "a coordinate"); });
}

TEST(TextScanner, ParsesIntegersExactly) {
    fabvdb::Progress progress;
    TextScanner scanner("", "f.off", TextSyntax{}, progress);
    EXPECT_EQ(scanner.parse_integer("42", "x"), 42);
    EXPECT_EQ(scanner.parse_integer("+7", "x"), 7);
    EXPECT_EQ(scanner.parse_integer("-12", "x"), -12);
    EXPECT_EQ(scanner.parse_integer("9223372036854775807", "x"), std::numeric_limits<int64_t>::max());
    EXPECT_EQ(scanner.parse_integer("-9223372036854775808", "x"), std::numeric_limits<int64_t>::min());
    for (const char* bad : {"", "+", "1.0", "0x10", "12a", "1e3", "9223372036854775808", "-9223372036854775809"}) {
        const std::string message = bad_input_message([&] { scanner.parse_integer(bad, "a face size"); });
        EXPECT_NE(message.find("a face size"), std::string::npos) << message;
    }
}

TEST(TextScanner, APlusBeforeASignIsNotANumber) {
    // "+-1" is no number in any of the formats; it must not read as -1.
    fabvdb::Progress progress;
    TextScanner scanner("", "n.obj", TextSyntax{}, progress);
    bad_input_message([&] { scanner.parse_double("+-1", "a coordinate"); });
    bad_input_message([&] { scanner.parse_double("+-1e3", "a coordinate"); });
    bad_input_message([&] { scanner.parse_integer("+-1", "a face size"); });
}

TEST(TextScanner, FailNamesTheCurrentLine) {
    fabvdb::Progress progress;
    TextScanner scanner("a\nb\nc\n", "dir/file.stl", TextSyntax{}, progress);
    scanner.next_line();
    scanner.next_line();
    EXPECT_EQ(bad_input_message([&] { scanner.fail("bad facet"); }), "dir/file.stl: line 3: bad facet");
}

std::string many_lines(int count) {
    std::string text;
    for (int i = 0; i < count; ++i) text += "v 1 2 3\n";  // 8 bytes a line
    return text;
}

struct Reports {
    std::vector<double> fractions;
};

int record(void* user, const char*, double fraction) {
    static_cast<Reports*>(user)->fractions.push_back(fraction);
    return 0;
}

TEST(TextScanner, ReportsTheFractionOfBytesRead) {
    const int lines = 20000;
    const std::string text = many_lines(lines);
    Reports reports;
    fabvdb::Progress progress(record, &reports, nullptr);
    TextScanner scanner(text, "x", TextSyntax{}, progress);
    for (int i = 0; i < lines; ++i) scanner.next_line();
    EXPECT_TRUE(scanner.at_end());
    ASSERT_GE(reports.fractions.size(), 2u);
    for (size_t k = 0; k < reports.fractions.size(); ++k) {
        EXPECT_GT(reports.fractions[k], 0.0);
        EXPECT_LE(reports.fractions[k], 1.0);
        if (k > 0) EXPECT_GT(reports.fractions[k], reports.fractions[k - 1]);
    }
    // Each fraction is a whole number of 8-byte lines out of the total.
    for (double f : reports.fractions) EXPECT_NEAR(f * lines, std::round(f * lines), 1e-6);
}

TEST(TextScanner, CancelStopsTheScan) {
    const int lines = 20000;
    const std::string text = many_lines(lines);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    TextScanner scanner(text, "x", TextSyntax{}, progress);
    try {
        for (int i = 0; i < lines; ++i) scanner.next_line();
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
    EXPECT_FALSE(scanner.at_end());
}

}  // namespace
