// TextScanner and the small file helpers shared by every text reader and writer of the io layer.
#include "io/text_scanner.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <system_error>

#include "core/chars.hpp"
#include "core/error.hpp"

namespace s4d {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
}  // namespace

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ParseError(path.string(), 0, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path.string(), 0, std::string("cannot open: ") + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw ParseError(path.string(), 0, "cannot determine the file size");
  in.seekg(0, std::ios::beg);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !in.read(text.data(), size)) throw ParseError(path.string(), 0, "read error");
  return text;
}

void write_text_file(const std::filesystem::path& path, std::string_view text) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write " + path.string() + ": " + std::strerror(errno));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw Error("cannot write " + path.string() + ": write failed (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw Error("cannot write " + path.string() + ": " + ec.message());
  }
}

std::string format_double(double v) {
  char buf[40];
  const auto r = double_to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void append_double(std::string& out, double v) {
  char buf[40];
  const auto r = double_to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_int(std::string& out, long long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string quote_token(std::string_view token) {
  std::string out = "'";
  std::size_t n = 0;
  for (char c : token) {
    if (++n > 24) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      out += buf;
    }
  }
  return out + "'";
}

bool parse_double(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* first = token.data();
  const char* last = first + token.size();
  double v = 0;
  const auto r = double_from_chars(first, last, v);
  if (r.ec == std::errc::result_out_of_range && token.size() < 64) {
    // from_chars reports underflow (1e-320) and overflow (1e999) alike; strtod tells them apart.
    char buf[64];
    std::memcpy(buf, first, token.size());
    buf[token.size()] = '\0';
    char* end = nullptr;
    v = std::strtod(buf, &end);
    if (end != buf + token.size() || !std::isfinite(v)) return false;
    out = v;
    return true;
  }
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v)) return false;
  out = v;
  return true;
}

bool parse_integer(std::string_view token, long long& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  long long v = 0;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
  if (r.ec != std::errc() || r.ptr != token.data() + token.size()) return false;
  out = v;
  return true;
}

TextScanner::TextScanner(std::string_view text, std::string origin)
    : text_(text), origin_(std::move(origin)) {}

void TextScanner::skip_blank() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (c == '#') {
      const std::size_t start = pos_;
      const std::size_t nl = text_.find('\n', pos_);
      pos_ = nl == std::string_view::npos ? text_.size() : nl;
      if (pos_ - start >= 2 && text_[start + 1] == '!') {
        std::string_view body = text_.substr(start + 2, pos_ - start - 2);
        while (!body.empty() && is_space(body.front())) body.remove_prefix(1);
        while (!body.empty() && is_space(body.back())) body.remove_suffix(1);
        directives_.push_back({line_, std::string(body)});
      }
    } else {
      return;
    }
  }
}

bool TextScanner::at_end() {
  skip_blank();
  return pos_ >= text_.size();
}

std::string_view TextScanner::next_token(std::string_view what) {
  skip_blank();
  if (pos_ >= text_.size())
    fail_at(tok_line_, "unexpected end of file: expected " + std::string(what));
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '#') ++pos_;
  tok_line_ = line_;
  return text_.substr(start, pos_ - start);
}

double TextScanner::next_double(std::string_view what) {
  const std::string_view tok = next_token(what);
  double v = 0;
  if (!parse_double(tok, v))
    fail("expected " + std::string(what) + " (a finite number), found " + quote_token(tok));
  return v;
}

long long TextScanner::next_int(std::string_view what, long long lo, long long hi) {
  const std::string_view tok = next_token(what);
  long long v = 0;
  if (!parse_integer(tok, v))
    fail("expected " + std::string(what) + " (an integer), found " + quote_token(tok));
  if (v < lo || v > hi)
    fail(std::string(what) + " is " + std::to_string(v) + ", must be in [" + std::to_string(lo) + ", " +
         std::to_string(hi) + "]");
  return v;
}

void TextScanner::skip_rest_of_line() {
  const std::size_t nl = text_.find('\n', pos_);
  if (nl == std::string_view::npos) {
    pos_ = text_.size();
  } else {
    pos_ = nl + 1;
    ++line_;
  }
}

void TextScanner::check_fits(long long count, long long tokens_each, std::string_view what) {
  // A token takes at least one byte and is followed by at least one separator, except the last.
  const long long budget = static_cast<long long>(remaining_bytes() / 2) + 1;
  if (count < 0 || tokens_each < 0 || (tokens_each > 0 && count > budget / tokens_each))
    fail("declared " + std::string(what) + " (" + std::to_string(count) +
         ") cannot fit in the rest of the file (" + std::to_string(remaining_bytes()) + " bytes)");
}

void TextScanner::fail(const std::string& message) const { fail_at(tok_line_, message); }

void TextScanner::fail_at(int line, const std::string& message) const {
  throw ParseError(origin_, line, message);
}

}  // namespace s4d
