// The pieces of the HTML pages (report/html.hpp): escaping, base64, embedded PNGs, tables.
#include <gtest/gtest.h>

#include <string>

#include "report/html.hpp"

namespace {

using fsweep::base64;
using fsweep::html_escape;

TEST(Html, EscapeMakesMarkupAndQuotesText) {
  EXPECT_EQ(html_escape("<b id=\"x\">a & 'b'</b>"),
            "&lt;b id=&quot;x&quot;&gt;a &amp; &#39;b&#39;&lt;/b&gt;");
  EXPECT_EQ(html_escape("plain text 1.5"), "plain text 1.5");
}

TEST(Html, Base64IsRfc4648WithPadding) {
  // The test vectors of RFC 4648 section 10.
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(Html, PngImgEmbedsTheBytesAndEscapesTheAltText) {
  EXPECT_EQ(fsweep::png_img("foo", "a 'b'"),
            "<img style='max-width:100%' alt='a &#39;b&#39;' src='data:image/png;base64,Zm9v'>");
}

TEST(Html, TableEscapesCellsAndPadsShortRows) {
  EXPECT_EQ(fsweep::html_table({"a", "<b>"}, {{"1"}, {"x&y", "2"}}),
            "<table><tr><th>a</th><th>&lt;b&gt;</th></tr>\n<tr><td>1</td><td></td></tr>\n"
            "<tr><td>x&amp;y</td><td>2</td></tr>\n</table>\n");
}

}  // namespace
