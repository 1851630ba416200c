#include "report/html.hpp"

#include <algorithm>
#include <cstdint>

namespace fsweep {
inline namespace report {

std::string html_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      v = (v << 8) | (j < n ? static_cast<unsigned char>(bytes[i + j]) : 0U);
    }
    for (std::size_t j = 0; j < 4; ++j) {
      out += j <= n ? kAlphabet[(v >> (18 - 6 * j)) & 63U] : '=';
    }
  }
  return out;
}

std::string png_img(std::string_view png, std::string_view alt, std::string_view style) {
  std::string out = "<img style='";
  out += style;
  out += "' alt='";
  out += html_escape(alt);
  out += "' src='data:image/png;base64,";
  out += base64(png);
  out += "'>";
  return out;
}

std::string html_table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  std::string out = "<table><tr>";
  for (const auto& h : header) out += "<th>" + html_escape(h) + "</th>";
  out += "</tr>\n";
  for (const auto& row : rows) {
    out += "<tr>";
    for (std::size_t i = 0; i < std::max(header.size(), row.size()); ++i) {
      out += "<td>" + (i < row.size() ? html_escape(row[i]) : std::string()) + "</td>";
    }
    out += "</tr>\n";
  }
  out += "</table>\n";
  return out;
}

std::string html_generator_tag(std::string_view generator) {
  return "<meta name='generator' content='" + html_escape(generator) + "'>";
}

std::string html_page_start(std::string_view title, std::string_view css, std::string_view generator) {
  std::string out = "<!DOCTYPE html>\n<html><head><meta charset='utf-8'>" + html_generator_tag(generator) +
                    "<link rel='icon' href='data:,'><title>";
  out += html_escape(title);
  out +=
      "</title><style>"
      "body{font-family:sans-serif;margin:1em 2em}table{border-collapse:collapse;font-size:13px}"
      "td,th{border:1px solid #ccc;padding:2px 6px;text-align:left}"
      ".warn{background:#fff3cd;border:1px solid #e0c060;padding:6px;margin:4px 0}";
  out += css;
  out += "</style></head><body>\n";
  return out;
}

}  // namespace report
}  // namespace fsweep
