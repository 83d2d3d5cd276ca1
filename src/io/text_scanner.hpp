// TextScanner: the one tokenizer behind the OFF, VECT and plain-text curve readers. It walks a
// whole file held in memory once, keeps the line number for errors, and never trusts a count.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace s4d {

// Reads a whole file into memory. Throws ParseError(file, 0, ...) if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);
// Writes `text` to `path` through a temporary file and a rename, so a failed write never leaves
// a half-written file behind. Throws Error.
void write_text_file(const std::filesystem::path& path, std::string_view text);

// Shortest text that reads back as exactly `v` (std::to_chars round trip).
std::string format_double(double v);
// The same appended in place (no temporary string: writers call this millions of times).
void append_double(std::string& out, double v);
void append_int(std::string& out, long long v);

// A "#!" line inside a file: a machine-readable hint our writers emit (grid layout, open curve).
struct Directive {
  int line = 0;
  std::string text;  // after "#!", trimmed
};

class TextScanner {
 public:
  // `origin` names the text in errors (usually the file path).
  TextScanner(std::string_view text, std::string origin);

  // Skips whitespace and '#' comments; true when nothing but those is left.
  bool at_end();
  // The next whitespace-delimited token; `what` names the expected item in the error at EOF.
  std::string_view next_token(std::string_view what);
  // A finite number (NaN, inf and out-of-range values are errors).
  double next_double(std::string_view what);
  // An integer in [lo, hi].
  long long next_int(std::string_view what, long long lo, long long hi);
  // Drops everything up to and including the next newline (e.g. a face's optional colour).
  void skip_rest_of_line();

  int line() const { return line_; }          // 1-based line of the scan position
  int token_line() const { return tok_line_; }  // line of the last token returned
  // Bytes not yet scanned: an upper bound on what a declared count may ask for.
  std::size_t remaining_bytes() const { return text_.size() - pos_; }
  // Throws unless `count` items of `tokens_each` tokens can fit in the remaining bytes (each
  // token needs at least one character and one separator). Call before allocating from a count.
  void check_fits(long long count, long long tokens_each, std::string_view what);
  const std::vector<Directive>& directives() const { return directives_; }
  const std::string& origin() const { return origin_; }

  [[noreturn]] void fail(const std::string& message) const;  // at the last token's line
  [[noreturn]] void fail_at(int line, const std::string& message) const;

 private:
  void skip_blank();

  std::string_view text_;
  std::string origin_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int tok_line_ = 1;
  std::vector<Directive> directives_;
};

// Printable excerpt of untrusted text for error messages (non-printables as \xNN, max 24 chars).
std::string quote_token(std::string_view token);
// Parses a whole token as a finite double / integer; false on any junk.
bool parse_double(std::string_view token, double& out);
bool parse_integer(std::string_view token, long long& out);

}  // namespace s4d
