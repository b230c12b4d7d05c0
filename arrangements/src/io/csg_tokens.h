// arrangements/src/io/csg_tokens.h (internal to load_csg_file: csg_parser.cpp)
//
// CsgTokens: the tokens of an OpenSCAD CSG file (load_csg.h), read from the file as a
// stream (FileBytes, 1 MiB at a time), with the line each starts on.
//   CsgTokens(path)  opens the file (InputError unreadable_file when it cannot be read); a
//                    UTF-8 byte order mark at its start is skipped
//   next()           the next token, skipping whitespace, "// ..." to the line's end and
//                    "/* ... */" (not nested); kind end at the end of the file
// Tokens:
//   word    [A-Za-z_$][A-Za-z0-9_$]*  (statement and argument names, true, false, undef)
//   number  [+-]? ( digits ( "." digits? )? | "." digits ) ( [eE] [+-]? digits )?, the
//           text as written (its exact value: parse_exact_decimal, rational_token.h)
//   string  "..." with the escapes \" \\ \n \r \t; text holds the value, line the line of
//           the opening quote (a string may span lines)
//   symbol  one of ( ) { } [ ] , ; =  (text is that character)
// Lines end in LF, CRLF or CR and are counted from 1.
// Throws InputError (malformed, "PATH: line N: ...") for an unterminated comment or string
// (N: where it began), an unknown escape in a string, a malformed number ("1.2.3",
// "1e", "-"), or a character that starts no token.
// Cost: linear in the file's size; memory: one buffer plus the current token.
#pragma once

#include <string>

#include "io/mesh_reader.h"

namespace arrangements::detail {

enum class CsgTokenKind { end, word, number, string, symbol };

struct CsgToken {
  CsgTokenKind kind = CsgTokenKind::end;
  std::string text;
  long line = 0;

  bool is(char symbol) const { return kind == CsgTokenKind::symbol && text.size() == 1 && text[0] == symbol; }
};

class CsgTokens {
 public:
  explicit CsgTokens(const std::string& path);

  CsgToken next();
  const std::string& path() const { return in_.path(); }
  long line() const { return line_; }  // the line of the next character

 private:
  int peek(std::size_t k = 0) {  // the k-th next byte (0..255), -1 past the end
    if (in_.available() <= k && in_.fill(k + 1) <= k) return -1;
    return static_cast<unsigned char>(in_.unread()[k]);
  }
  void advance();  // one byte, counting line ends
  void skip_space_and_comments();
  void read_number(CsgToken& token);
  void read_string(CsgToken& token);

  FileBytes in_;
  long line_ = 1;
  bool after_cr_ = false;  // the last byte was a CR (a following LF ends no new line)
};

}  // namespace arrangements::detail
