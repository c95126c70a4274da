// base::printable / quoted: file-supplied text made safe for a one-line message.
#include "base/Printable.hpp"

#include <gtest/gtest.h>
#include <string>

namespace speculum::render {
namespace {

bool hasRawControl(const std::string& s) {
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F) {
            return true;
        }
    }
    return false;
}

TEST(Printable, PlainTextAndLettersStayAsTheyAre) {
    EXPECT_EQ(base::printable("Chrome ball"), "Chrome ball");
    EXPECT_EQ(base::printable("caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x98\x80"),
              "caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x98\x80");
    EXPECT_EQ(base::printable(""), "");
    EXPECT_EQ(base::quoted("teapot"), "'teapot'");
}

TEST(Printable, ControlCharactersBecomeVisibleEscapes) {
    EXPECT_EQ(base::printable("a\nb"), "a\\nb");
    EXPECT_EQ(base::printable("a\r\tb"), "a\\r\\tb");
    EXPECT_EQ(base::printable("\x1b[31mred"), "\\x1b[31mred");
    EXPECT_EQ(base::printable(std::string("nul\0x", 5)), "nul\\x00x");
    EXPECT_EQ(base::printable("del\x7f"), "del\\x7f");
    // A backslash is doubled, so "\n" typed in a name cannot pass for an escaped newline.
    EXPECT_EQ(base::printable("a\\nb"), "a\\\\nb");
    // A forged message line stays on the line of the real one.
    const std::string forged = base::printable("x\nspeculum: error: all is fine\n");
    EXPECT_FALSE(hasRawControl(forged)) << forged;
    EXPECT_EQ(forged, "x\\nspeculum: error: all is fine\\n");
}

TEST(Printable, InvalidUtf8IsEscapedBytewise) {
    EXPECT_EQ(base::printable("a\xff"
                              "b"),
              "a\\xffb");
    EXPECT_EQ(base::printable("\xC0\xAF"), "\\xc0\\xaf");                   // overlong '/'
    EXPECT_EQ(base::printable("\xED\xA0\x80"), "\\xed\\xa0\\x80");          // a UTF-16 surrogate
    EXPECT_EQ(base::printable("\xE6\x97"), "\\xe6\\x97");                   // cut short
    EXPECT_EQ(base::printable("\xF4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80"); // beyond U+10FFFF
}

TEST(Printable, InvisibleAndReorderingCharactersAreEscaped) {
    EXPECT_EQ(base::printable("\xC2\x9B"
                              "31m"),
              "\\u009b31m"); // C1 CSI
    EXPECT_EQ(base::printable("ab\xE2\x80\xAE"
                              "cd"),
              "ab\\u202ecd");                                  // right-to-left override
    EXPECT_EQ(base::printable("x\xE2\x81\xA6y"), "x\\u2066y"); // left-to-right isolate
    EXPECT_EQ(base::printable("line\xE2\x80\xA8"
                              "two"),
              "line\\u2028two"); // line separator
    EXPECT_EQ(base::printable("a\xE2\x80\x8B"
                              "b"),
              "a\\u200bb");                                      // zero-width space
    EXPECT_EQ(base::printable("\xEF\xBB\xBFkey"), "\\ufeffkey"); // byte order mark
}

TEST(Printable, LongTextKeepsItsBeginningAndEnd) {
    const std::string longName = std::string(500, 'a') + "END";
    const std::string shown = base::printable(longName, 40);
    EXPECT_LE(shown.size(), 40u);
    EXPECT_EQ(shown.substr(0, 5), "aaaaa");
    EXPECT_NE(shown.find("..."), std::string::npos);
    EXPECT_EQ(shown.substr(shown.size() - 3), "END");
    // Exactly at the limit: unchanged.
    EXPECT_EQ(base::printable(std::string(40, 'b'), 40), std::string(40, 'b'));
    EXPECT_NE(base::printable(std::string(41, 'b'), 40), std::string(41, 'b'));
}

TEST(Printable, ShorteningNeverCutsAnEscapeOrACharacter) {
    std::string text;
    for (int i = 0; i < 100; ++i) {
        text += "\x1b\xC3\xA9";
    }
    const std::string shown = base::printable(text, 21);
    EXPECT_FALSE(hasRawControl(shown));
    // 9 units on each side of the ellipsis, every one whole.
    const std::size_t dots = shown.find("...");
    ASSERT_NE(dots, std::string::npos);
    const std::string head = shown.substr(0, dots);
    const std::string tail = shown.substr(dots + 3);
    EXPECT_EQ(head, "\\x1b\xC3\xA9\\x1b\xC3\xA9\\x1b\xC3\xA9\\x1b\xC3\xA9\\x1b");
    EXPECT_EQ(tail, "\xC3\xA9\\x1b\xC3\xA9\\x1b\xC3\xA9\\x1b\xC3\xA9\\x1b\xC3\xA9");
}

TEST(Printable, HugeTextIsShortenedQuickly) {
    // An 8 MiB name in a file: the message stays short and building it does not take memory per byte.
    const std::string huge(8u << 20, 'x');
    const std::string shown = base::quoted(huge);
    EXPECT_LE(shown.size(), 202u);
    EXPECT_EQ(shown.front(), '\'');
    EXPECT_EQ(shown.back(), '\'');
}

} // namespace
} // namespace speculum::render
