#pragma once
/// @file html.hpp
/// Pieces of the self-contained HTML pages (compare.html, compare_html.cpp; report.html,
/// report_page.cpp): text escaping, embedded PNGs, tables of CSV cells and the page frame. A
/// page built from them needs no other file, script or network: styles are inline and images
/// are data: URIs.

#include <string>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace report {

/// `s` safe as HTML text and as a quoted attribute value (either quote): & < > " ' escaped.
[[nodiscard]] std::string html_escape(std::string_view s);

/// Standard base64 (RFC 4648) with padding.
[[nodiscard]] std::string base64(std::string_view bytes);

/// An <img> of the PNG file bytes `png`, embedded as a data: URI, with the alt text `alt`
/// (escaped) and the inline style `style` (not escaped: a literal of the caller's).
[[nodiscard]] std::string png_img(std::string_view png, std::string_view alt,
                                  std::string_view style = "max-width:100%");

/// A <table> of text cells (each escaped), `header` as its first row of <th>; rows shorter
/// than the header are padded with empty cells.
[[nodiscard]] std::string html_table(const std::vector<std::string>& header,
                                     const std::vector<std::vector<std::string>>& rows);

/// The start of a page up to and including <body>: doctype, UTF-8, an empty icon (so a browser
/// asks for no icon file), the title (escaped) and one inline style sheet: the pages' common
/// rules followed by `css`, and a generator meta tag naming the command that wrote the page
/// (`<meta name='generator' content='GENERATOR'>`: how `fsweep report --out` recognises a page
/// it may replace).
[[nodiscard]] std::string html_page_start(std::string_view title, std::string_view css,
                                          std::string_view generator);

/// The generator meta tag html_page_start() writes for `generator`.
[[nodiscard]] std::string html_generator_tag(std::string_view generator);

}  // namespace report
}  // namespace fsweep
