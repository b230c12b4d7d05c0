// The OpenSCAD CSG subset of load_csg.h: statements into a CsgNode tree (csg_parser.h).
// Open statements are kept on an explicit stack (no recursion), so any nesting up to
// kMaxCsgDepth parses in constant stack space.
#include "io/csg_parser.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "io/csg_tokens.h"
#include "io/mesh_format.h"
#include "io/rational_token.h"

namespace arrangements::detail {

namespace {

// An argument's value: a number, string or word, or a vector ('[') of values.
struct Value {
  CsgTokenKind kind = CsgTokenKind::end;
  std::string text;
  std::vector<Value> items;
  long line = 0;
  bool is_vector() const { return kind == CsgTokenKind::symbol; }
};

constexpr int kMaxValueDepth = 64;  // vectors in vectors: a matrix needs 2
// A matrix entry multiplies every coordinate of its operands: its size is bounded (a mesh
// file's own rationals are not).
constexpr std::size_t kMaxMatrixEntryDigits = 100000;

enum class Block { top, union_of, difference, intersection, transform };

// An open statement: its children so far, the transform in effect for them.
struct Frame {
  Block block;
  std::string name;  // as written, for messages
  long line;
  bool braced;  // children in { }, else exactly one child statement
  std::vector<CsgNode> children;
  std::shared_ptr<const ExactAffine> transform;
};

std::string describe(const CsgToken& t) {
  switch (t.kind) {
    case CsgTokenKind::end:
      return "the end of the file";
    case CsgTokenKind::string:
      return "a string";
    default:
      return detail::quoted(t.text);
  }
}

class Parser {
 public:
  explicit Parser(const std::string& path) : tokens_(path), path_(path) {
    folder_ = std::filesystem::path(path).parent_path();
  }
  CsgProgram run();

 private:
  void next() { token_ = tokens_.next(); }
  [[noreturn]] void refuse_here(InputErrorKind kind, long line, const std::string& what) const {
    refuse_at_line(kind, path_, line, what);
  }
  [[noreturn]] void unexpected(const std::string& expected) const {
    refuse_here(InputErrorKind::malformed, token_.line, "expected " + expected + ", found " + describe(token_));
  }
  void expect(char symbol, const std::string& context) {
    if (!token_.is(symbol)) unexpected("'" + std::string(1, symbol) + "' " + context);
    next();
  }
  void statement();
  void import(long line);
  void open(Block block, std::string name, long line, std::shared_ptr<const ExactAffine> transform);
  void add(CsgNode node);
  CsgNode close(Frame& frame);
  std::optional<Value> arguments(const std::string& statement, std::string_view wanted);
  void value(bool keep, Value& out, int depth);
  ExactAffine matrix(const Value& m, long line);

  CsgTokens tokens_;
  std::string path_;
  std::filesystem::path folder_;
  CsgToken token_;
  std::vector<Frame> frames_;
  std::vector<CsgImport> imports_;
};

CsgProgram Parser::run() {
  frames_.push_back(Frame{Block::top, "", 0, true, {}, nullptr});
  // Only a braced block (or the top) meets '}', ';' or the end here: a statement without
  // braces is opened only before the word of its child statement (open()), which closes it.
  for (next();;) {
    const Frame& frame = frames_.back();
    if (token_.kind == CsgTokenKind::end) {
      if (frames_.size() == 1) break;
      refuse_here(InputErrorKind::malformed, token_.line,
                  "unbalanced braces: the block of " + frame.name + "() at line " + std::to_string(frame.line) +
                      " is not closed at the end of the file");
    }
    if (token_.is('}')) {
      if (frames_.size() == 1)
        refuse_here(InputErrorKind::malformed, token_.line, "unbalanced braces: '}' closes no block");
      next();
      Frame closed = std::move(frames_.back());
      frames_.pop_back();
      add(close(closed));
    } else if (token_.is(';')) {  // an empty statement (also: the optional ';' after a block)
      next();
    } else if (token_.kind == CsgTokenKind::word) {
      statement();
    } else {
      unexpected("a statement");
    }
  }
  if (imports_.empty())
    refuse(InputErrorKind::empty_mesh, path_, "no operand: the file has no import() statement");
  CsgProgram program;
  program.tree = close(frames_.back());
  program.imports = std::move(imports_);
  return program;
}

void Parser::statement() {
  const std::string name = token_.text;
  const long line = token_.line;
  Block block;
  if (name == "union" || name == "group") block = Block::union_of;
  else if (name == "difference") block = Block::difference;
  else if (name == "intersection") block = Block::intersection;
  else if (name == "multmatrix") block = Block::transform;
  else if (name == "import") block = Block::top;  // not a block: handled below
  else
    refuse_here(InputErrorKind::malformed, line,
                "unknown statement " + detail::quoted(name) +
                    " (known: union, group, difference, intersection, multmatrix, import)");
  next();
  expect('(', "after " + name);
  if (name == "import") return import(line);
  std::shared_ptr<const ExactAffine> transform = frames_.back().transform;
  const std::optional<Value> m = arguments(name, block == Block::transform ? "m" : "");
  if (block == Block::transform) {
    if (!m) refuse_here(InputErrorKind::malformed, line, "multmatrix() without its matrix m");
    const ExactAffine own = matrix(*m, line);
    const ExactAffine composed = transform ? compose(*transform, own) : own;
    transform = is_identity(composed) ? nullptr : std::make_shared<const ExactAffine>(composed);
  }
  if (token_.is(';')) {  // no children
    next();
    Frame empty{block, name, line, true, {}, nullptr};
    add(close(empty));
  } else if (token_.is('{') || token_.kind == CsgTokenKind::word) {
    open(block, name, line, std::move(transform));
  } else {
    unexpected("'{', ';' or a statement after " + name + "(...)");
  }
}

void Parser::open(Block block, std::string name, long line, std::shared_ptr<const ExactAffine> transform) {
  if (frames_.size() > kMaxCsgDepth)
    refuse_here(InputErrorKind::too_large, line,
                "statements nested more than " + std::to_string(kMaxCsgDepth) + " deep");
  const bool braced = token_.is('{');
  if (braced) next();
  frames_.push_back(Frame{block, std::move(name), line, braced, {}, std::move(transform)});
}

void Parser::import(long line) {
  const std::optional<Value> file = arguments("import", "file");
  if (!file || file->kind != CsgTokenKind::string || file->text.empty())
    refuse_here(InputErrorKind::malformed, line, "import() needs a file name: import(file = \"name.off\")");
  expect(';', "after import(...)");
  std::filesystem::path resolved(file->text);
  if (resolved.is_relative()) resolved = folder_ / resolved;
  const std::string name = resolved.string();
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(resolved, ec);
  if (ec || !std::filesystem::exists(status))
    refuse_here(InputErrorKind::unreadable_file, line, "imported file '" + name + "' does not exist");
  if (!std::filesystem::is_regular_file(status))
    refuse_here(InputErrorKind::unreadable_file, line, "imported file '" + name + "' is not a regular file");
  if (!format_of(name, kLoadFormats))
    refuse_here(InputErrorKind::unknown_format, line,
                "imported file '" + name + "' has an unknown extension (supported: " + extension_list(kLoadFormats) +
                    ", any case)");
  if (imports_.size() >= kMaxIndexCount)
    refuse_here(InputErrorKind::too_large, line, "more than " + std::to_string(kMaxIndexCount) + " imports");
  imports_.push_back(CsgImport{name, line, frames_.back().transform});
  add(CsgNode::leaf(static_cast<int>(imports_.size() - 1)));  // may close statements: after the transform is taken
}

// Adds a finished child to the innermost open statement, closing the statements that take
// one child without braces as they get it.
void Parser::add(CsgNode node) {
  for (;;) {
    Frame& frame = frames_.back();
    frame.children.push_back(std::move(node));
    if (frame.braced) return;
    Frame closed = std::move(frame);
    frames_.pop_back();
    node = close(closed);
  }
}

CsgNode Parser::close(Frame& frame) {
  std::vector<CsgNode>& children = frame.children;
  switch (frame.block) {
    case Block::union_of:
      return CsgNode::of(BooleanOp::Union, std::move(children));
    case Block::difference: {  // of nothing: empty, as the Union of nothing
      const BooleanOp op = children.empty() ? BooleanOp::Union : BooleanOp::Difference;
      return CsgNode::of(op, std::move(children));
    }
    case Block::intersection:
      if (children.empty())
        refuse_here(InputErrorKind::malformed, frame.line,
                    "intersection() of nothing (an intersection needs at least one child)");
      return CsgNode::of(BooleanOp::Intersection, std::move(children));
    case Block::top:
    case Block::transform:
      break;
  }
  if (children.size() == 1) return std::move(children[0]);
  return CsgNode::of(BooleanOp::Union, std::move(children));
}

// The arguments up to ')'; returns the one named `wanted` or, unnamed, the first (only
// kept when wanted is not empty); the others are read and dropped.
std::optional<Value> Parser::arguments(const std::string& statement, std::string_view wanted) {
  std::optional<Value> found;
  if (token_.is(')')) {
    next();
    return found;
  }
  for (std::size_t position = 0;; ++position) {
    Value v;
    bool keep = false;
    if (token_.kind == CsgTokenKind::word) {  // a name, or a word value (true, undef, ...)
      CsgToken word = std::move(token_);
      next();
      if (token_.is('=')) {
        next();
        keep = !wanted.empty() && word.text == wanted;
        value(keep, v, 0);
      } else {
        keep = !wanted.empty() && position == 0;
        v = Value{word.kind, std::move(word.text), {}, word.line};
      }
    } else {
      keep = !wanted.empty() && position == 0;
      value(keep, v, 0);
    }
    if (keep) {
      if (found) refuse_here(InputErrorKind::malformed, v.line, statement + "(): " + std::string(wanted) + " given twice");
      found = std::move(v);
    }
    if (token_.is(')')) break;
    expect(',', "or ')' in the arguments of " + statement + "()");
  }
  next();
  return found;
}

void Parser::value(bool keep, Value& out, int depth) {
  if (depth > kMaxValueDepth)
    refuse_here(InputErrorKind::too_large, token_.line,
                "vectors nested more than " + std::to_string(kMaxValueDepth) + " deep");
  out.line = token_.line;
  if (token_.kind == CsgTokenKind::number || token_.kind == CsgTokenKind::string ||
      token_.kind == CsgTokenKind::word) {
    if (keep) {
      out.kind = token_.kind;
      out.text = std::move(token_.text);
    }
    next();
    return;
  }
  if (!token_.is('[')) unexpected("a value");
  out.kind = CsgTokenKind::symbol;
  next();
  if (token_.is(']')) {
    next();
    return;
  }
  for (;;) {
    Value item;
    value(keep, item, depth + 1);
    if (keep) out.items.push_back(std::move(item));
    if (token_.is(']')) break;
    expect(',', "or ']' in a vector");
  }
  next();
}

ExactAffine Parser::matrix(const Value& m, long line) {
  const std::string shape =
      "multmatrix: m must be a 4 x 4 matrix of numbers, [[a, b, c, d], [e, f, g, h], [i, j, k, l], [0, 0, 0, 1]]";
  if (!m.is_vector() || m.items.size() != 4) refuse_here(InputErrorKind::malformed, m.line, shape);
  std::array<std::array<CGAL::Gmpq, 4>, 4> e;
  for (int r = 0; r < 4; ++r) {
    const Value& row = m.items[r];
    if (!row.is_vector() || row.items.size() != 4) refuse_here(InputErrorKind::malformed, row.line, shape);
    for (int c = 0; c < 4; ++c) {
      const Value& entry = row.items[c];
      if (entry.kind != CsgTokenKind::number) refuse_here(InputErrorKind::malformed, entry.line, shape);
      const RationalParse p = parse_exact_decimal(entry.text, e[r][c], kMaxMatrixEntryDigits);
      if (p == RationalParse::huge)
        refuse_here(InputErrorKind::too_large, entry.line,
                    "multmatrix: " + detail::quoted(entry.text) + " has more than " + std::to_string(kMaxMatrixEntryDigits) +
                        " digits or an exponent beyond " + std::to_string(kMaxDecimalExponent));
      if (p != RationalParse::ok) refuse_here(InputErrorKind::malformed, entry.line, shape);
    }
  }
  const Value& last = m.items[3];
  for (int c = 0; c < 4; ++c)
    if (e[3][c] != CGAL::Gmpq(c == 3 ? 1 : 0))
      refuse_here(InputErrorKind::malformed, last.line,
                  "multmatrix: the last row must be [0, 0, 0, 1], found [" + last.items[0].text + ", " +
                      last.items[1].text + ", " + last.items[2].text + ", " + last.items[3].text + "]");
  ExactAffine t;
  for (int r = 0; r < 3; ++r) t.rows[r] = e[r];
  if (determinant(t) == CGAL::Gmpq(0))
    refuse_here(InputErrorKind::malformed, line, "singular multmatrix (the determinant of its 3 x 3 part is 0)");
  return t;
}

}  // namespace

CsgProgram parse_csg(const std::string& path) { return Parser(path).run(); }

}  // namespace arrangements::detail
