// The tokenizer of OpenSCAD CSG files (csg_tokens.h).
#include "io/csg_tokens.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace arrangements::detail {

namespace {

bool is_digit(int c) { return c >= '0' && c <= '9'; }
bool is_word_start(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$'; }
bool is_word_char(int c) { return is_word_start(c) || is_digit(c); }
bool is_symbol(int c) {
  return c == '(' || c == ')' || c == '{' || c == '}' || c == '[' || c == ']' || c == ',' || c == ';' || c == '=';
}

std::size_t digit_run(std::string_view s, std::size_t i) {
  const std::size_t start = i;
  while (i < s.size() && is_digit(s[i])) ++i;
  return i - start;
}

// The number grammar of csg_tokens.h.
bool is_number(std::string_view s) {
  std::size_t i = s.empty() || (s[0] != '+' && s[0] != '-') ? 0 : 1;
  const std::size_t whole = digit_run(s, i);
  i += whole;
  std::size_t fraction = 0;
  if (i < s.size() && s[i] == '.') {
    fraction = digit_run(s, i + 1);
    i += 1 + fraction;
  }
  if (whole == 0 && fraction == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t exponent = digit_run(s, i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == s.size();
}

}  // namespace

CsgTokens::CsgTokens(const std::string& path) : in_(path) {
  if (in_.fill(3) >= 3 && std::string_view(in_.unread(), 3) == "\xEF\xBB\xBF") in_.consume(3);
}

void CsgTokens::advance() {
  const char c = in_.unread()[0];
  in_.consume(1);
  if (c == '\n') {
    if (!after_cr_) ++line_;
    after_cr_ = false;
  } else if (c == '\r') {
    ++line_;
    after_cr_ = true;
  } else {
    after_cr_ = false;
  }
}

void CsgTokens::skip_space_and_comments() {
  for (int c = peek(); c != -1; c = peek()) {
    if (is_space(static_cast<char>(c))) {
      advance();
    } else if (c == '/' && peek(1) == '/') {
      while ((c = peek()) != -1 && c != '\n' && c != '\r') advance();
    } else if (c == '/' && peek(1) == '*') {
      const long start = line_;
      advance();
      advance();
      for (;;) {
        c = peek();
        if (c == -1) refuse_at_line(InputErrorKind::malformed, path(), start, "unterminated comment '/*'");
        if (c == '*' && peek(1) == '/') break;
        advance();
      }
      advance();
      advance();
    } else {
      return;
    }
  }
}

void CsgTokens::read_number(CsgToken& token) {
  token.kind = CsgTokenKind::number;
  int c = peek();
  for (;;) {
    token.text += static_cast<char>(c);
    advance();
    const char last = token.text.back();
    c = peek();
    const bool exponent_sign = (c == '+' || c == '-') && (last == 'e' || last == 'E');
    if (!exponent_sign && !is_word_char(c) && c != '.') break;
  }
  if (!is_number(token.text))
    refuse_at_line(InputErrorKind::malformed, path(), token.line, detail::quoted(token.text) + " is not a number");
}

void CsgTokens::read_string(CsgToken& token) {
  token.kind = CsgTokenKind::string;
  advance();  // the opening quote
  for (;;) {
    int c = peek();
    if (c == -1) refuse_at_line(InputErrorKind::malformed, path(), token.line, "unterminated string");
    advance();
    if (c == '"') return;
    if (c == '\\') {
      const int e = peek();
      if (e == -1) refuse_at_line(InputErrorKind::malformed, path(), token.line, "unterminated string");
      if (e == '"' || e == '\\') c = e;
      else if (e == 'n') c = '\n';
      else if (e == 'r') c = '\r';
      else if (e == 't') c = '\t';
      else
        refuse_at_line(InputErrorKind::malformed, path(), line_,
                       "unknown escape " + detail::quoted(std::string{'\\', static_cast<char>(e)}) + " in a string");
      advance();
    }
    token.text += static_cast<char>(c);
  }
}

CsgToken CsgTokens::next() {
  skip_space_and_comments();
  CsgToken token;
  token.line = line_;
  const int c = peek();
  if (c == -1) return token;
  if (is_word_start(c)) {
    token.kind = CsgTokenKind::word;
    for (int w = c; is_word_char(w); w = peek()) {
      token.text += static_cast<char>(w);
      advance();
    }
  } else if (is_digit(c) || c == '.' || c == '+' || c == '-') {
    read_number(token);
  } else if (c == '"') {
    read_string(token);
  } else if (is_symbol(c)) {
    token.kind = CsgTokenKind::symbol;
    token.text = static_cast<char>(c);
    advance();
  } else {
    refuse_at_line(InputErrorKind::malformed, path(), line_,
                   "unexpected character " + detail::quoted(std::string(1, static_cast<char>(c))));
  }
  return token;
}

}  // namespace arrangements::detail
