// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading mesh files as CGAL's readers read them, for the checks that come
// before those readers (IO/read_triangle_mesh.h): the file format, tokens
// and lines, the line-by-line diagnosis of an OFF file, the plain OFF reader,
// the strict OBJ parse, the character scanners of operator>>, and the base of
// the checks of announced counts.
#ifndef GEODESIC_RIDGE_INTERNAL_MESH_FILE_TEXT_H
#define GEODESIC_RIDGE_INTERNAL_MESH_FILE_TEXT_H

#include <Geodesic_ridge/exceptions.h>

#include <CGAL/IO/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace mesh_io {

enum class Mesh_file_format { OFF, OBJ, PLY };

[[noreturn]] inline void file_error(const std::string& filename, const std::string& what)
{
  throw Mesh_file_error(filename + ": " + what);
}

inline Mesh_file_format mesh_file_format(const std::string& filename)
{
  std::string ext = std::filesystem::path(filename).extension().string();
  for(char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if(ext == ".off")
    return Mesh_file_format::OFF;
  if(ext == ".obj")
    return Mesh_file_format::OBJ;
  if(ext == ".ply")
    return Mesh_file_format::PLY;
  file_error(filename, ext.empty() ? std::string("file name has no extension; expected .off, .obj or .ply")
                                   : "unsupported extension '" + ext + "'; expected .off, .obj or .ply");
}

// Whole-token parsers. `strtod` accepts "nan", "inf" and overflowing values
// (giving infinity), which CGAL's readers reject as malformed: parsing them
// here lets the validation name the vertex with the non-finite coordinate.
inline bool parse_double(const std::string& token, double& value)
{
  const char* begin = token.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  return end != begin && *end == '\0';
}

inline bool parse_integer(const std::string& token, long long& value)
{
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(begin, &end, 10);
  return end != begin && *end == '\0' && errno != ERANGE;
}

// The lines of a text file, split into whitespace-separated tokens, with
// `#` comments removed (as CGAL's OFF and OBJ readers do).
class Token_lines
{
  std::ifstream m_in;
  std::size_t m_line_number = 0;

public:
  explicit Token_lines(const std::string& filename) : m_in(filename) {}

  std::size_t line_number() const { return m_line_number; }

  // The tokens of the next line that has some; false at the end of the file.
  bool next(std::vector<std::string>& tokens)
  {
    std::string line;
    while(std::getline(m_in, line))
    {
      ++m_line_number;
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos)
        line.erase(hash);
      std::istringstream words(line);
      tokens.clear();
      for(std::string word; words >> word;)
        tokens.push_back(word);
      if(!tokens.empty())
        return true;
    }
    return false;
  }
};

// The steps of `diagnose_OFF()`, in file order: header, vertices, faces.
class OFF_diagnosis
{
public:
  explicit OFF_diagnosis(const std::string& filename) : filename_(filename), lines_(filename) {}

  // The keyword and the counts; false for an OFF variant.
  bool read_header()
  {
    if(!lines_.next(tokens_))
      file_error(filename_, "file is empty (no OFF header)");
    if(tokens_[0] != "OFF")
    {
      const std::string& t = tokens_[0];
      if(t.size() > 3 && t.compare(t.size() - 3, 3, "OFF") == 0)
        return false;
      file_error(filename_, where() + "expected the OFF header, found '" + t + "'");
    }
    if(tokens_.size() > 1)
      tokens_.erase(tokens_.begin()); // "OFF V F E" on one line
    else if(!lines_.next(tokens_))
      file_error(filename_, "file ends after the OFF keyword (no 'V F E' counts)");
    if(tokens_[0] == "BINARY")
      return false;
    long long counts[3];
    if(tokens_.size() != 3 || !parse_integer(tokens_[0], counts[0]) || !parse_integer(tokens_[1], counts[1]) ||
       !parse_integer(tokens_[2], counts[2]) || counts[0] < 0 || counts[1] < 0)
      file_error(filename_, where() + "expected the OFF counts 'V F E' (three integers)");
    nv_ = static_cast<std::size_t>(counts[0]);
    nf_ = static_cast<std::size_t>(counts[1]);
    return true;
  }

  template <class Point>
  void read_vertices(std::vector<Point>& points)
  {
    points.clear();
    for(std::size_t i = 0; i < nv_; ++i)
    {
      if(!lines_.next(tokens_))
        truncated(std::to_string(i) + " vertices");
      if(tokens_.size() < 3)
        file_error(filename_, where() + "vertex " + std::to_string(i) + " has " + std::to_string(tokens_.size()) +
                                " coordinate(s), expected 3");
      double c[3];
      for(int k = 0; k < 3; ++k)
        if(!parse_double(tokens_[k], c[k]))
          file_error(filename_, where() + "vertex " + std::to_string(i) + ": '" + tokens_[k] + "' is not a number");
      points.emplace_back(c[0], c[1], c[2]);
    }
  }

  void read_faces(std::vector<std::vector<std::size_t>>& polygons)
  {
    polygons.clear();
    for(std::size_t j = 0; j < nf_; ++j)
    {
      if(!lines_.next(tokens_))
        truncated(std::to_string(j) + " faces");
      long long n = 0;
      if(!parse_integer(tokens_[0], n) || n < 0)
        file_error(filename_, where() + "face " + std::to_string(j) + ": '" + tokens_[0] + "' is not a vertex count");
      if(tokens_.size() < static_cast<std::size_t>(n) + 1)
        file_error(filename_, where() + "face " + std::to_string(j) + " announces " + std::to_string(n) +
                                " vertices but lists " + std::to_string(tokens_.size() - 1));
      polygons.emplace_back();
      for(std::size_t k = 1; k <= static_cast<std::size_t>(n); ++k)
      {
        long long id = 0;
        if(!parse_integer(tokens_[k], id) || id < 0)
          file_error(filename_, where() + "face " + std::to_string(j) + ": '" + tokens_[k] +
                                  "' is not a vertex index");
        polygons.back().push_back(static_cast<std::size_t>(id));
      }
    }
  }

private:
  std::string where() const { return "line " + std::to_string(lines_.line_number()) + ": "; }

  [[noreturn]] void truncated(const std::string& what) const
  {
    file_error(filename_, "file is truncated: the header announces " + std::to_string(nv_) + " vertices and " +
                            std::to_string(nf_) + " faces, but it ends after " + what);
  }

  const std::string& filename_;
  Token_lines lines_;
  std::vector<std::string> tokens_;
  std::size_t nv_ = 0, nf_ = 0; // the counts of the header
};

// Re-reads an ASCII OFF file that CGAL's reader rejected, to say why. Throws
// `Mesh_file_error` naming the line for a syntax error or a truncation;
// otherwise fills the soup, whose validation then names the semantic problem
// (an index out of range, a NaN coordinate). Returns false for the OFF
// variants it does not know (COFF, NOFF, binary, ...).
template <class Point>
bool diagnose_OFF(const std::string& filename, std::vector<Point>& points,
                  std::vector<std::vector<std::size_t>>& polygons)
{
  OFF_diagnosis off(filename);
  if(!off.read_header())
    return false;
  off.read_vertices(points);
  off.read_faces(polygons);
  return true;
}

// The plainest ASCII OFF files (most files): "OFF", the three counts on one
// line, then one vertex per line (three numbers) and one face per line (its
// size, at least 3, then as many indices below the vertex count), no comment.
// They are read as CGAL's reader reads them: every number is parsed as it
// does (`sscanf("%lf")`, that is `strtod`, on a token of digits, a point, an
// exponent and signs; an overflow is left to it), lines after the last face
// are not read. CGAL's reader
// makes a string stream per line, which costs more than everything else the
// package does with the mesh; this takes a fraction of it. Returns false,
// with the soup cleared, for any other file (comments, colors, normals,
// binary, a short file, an index out of range, anything unexpected): CGAL's
// reader then reads it as before.
typedef std::pair<const char*, const char*> Plain_OFF_token;

// A token of a plain OFF file as an unsigned integer of at most 9 digits
// (CGAL reads it as a double, then casts it).
inline bool plain_OFF_integer(const Plain_OFF_token& t, std::size_t& value)
{
  if(t.second - t.first > 9) return false;
  value = 0;
  for(const char* c = t.first; c != t.second; ++c)
  {
    if(*c < '0' || *c > '9') return false;
    value = 10 * value + static_cast<std::size_t>(*c - '0');
  }
  return true;
}

// A token of a plain OFF file as a number:
// [+-]digits[.digits][(e|E)[+-]digits], the integer or the fraction part
// possibly empty, not both; the token must be followed by a blank, newline or
// NUL (strtod stops there).
inline bool plain_OFF_number(const Plain_OFF_token& t, double& value)
{
  auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  const char* c = t.first;
  if(c != t.second && (*c == '+' || *c == '-')) ++c;
  std::size_t digits = 0;
  for(; c != t.second && is_digit(*c); ++c) ++digits;
  if(c != t.second && *c == '.')
    for(++c; c != t.second && is_digit(*c); ++c) ++digits;
  if(digits == 0) return false;
  if(c != t.second && (*c == 'e' || *c == 'E'))
  {
    ++c;
    if(c != t.second && (*c == '+' || *c == '-')) ++c;
    if(c == t.second || !is_digit(*c)) return false;
    while(c != t.second && is_digit(*c)) ++c;
  }
  if(c != t.second) return false;
  // std::from_chars rounds as strtod does (correctly), several times faster;
  // it takes no leading '+', and anything it refuses (an overflow, an
  // underflow) goes to strtod, as before
  const char* first = *t.first == '+' ? t.first + 1 : t.first;
  const auto parsed = std::from_chars(first, t.second, value);
  if(parsed.ec == std::errc() && parsed.ptr == t.second) return true;
  char* stop = nullptr;
  value = std::strtod(t.first, &stop);
  return stop == t.second && std::isfinite(value); // CGAL's reader rejects an overflow
}

template <class Point>
bool read_plain_OFF(const std::string& filename, std::vector<Point>& points,
                    std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream in(filename, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(in.bad())
    return false;
  const char* p = text.c_str();
  const char* const end = p + text.size();
  // CGAL skips std::isspace between lines; inside a line, every one but the newline
  auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  auto skip_spaces = [&] { while(p != end && (is_blank(*p) || *p == '\n')) ++p; };
  // the tokens of the line at p (none if it has a comment); p moves past it
  std::vector<std::pair<const char*, const char*>> tokens;
  auto read_line = [&]() -> bool {
    tokens.clear();
    while(p != end && *p != '\n')
    {
      if(*p == '#')
        return false;
      if(is_blank(*p)) { ++p; continue; }
      const char* first = p;
      while(p != end && *p != '\n' && !is_blank(*p) && *p != '#') ++p;
      tokens.emplace_back(first, p);
    }
    return true;
  };
  auto fail = [&] {
    points.clear();
    polygons.clear();
    return false;
  };

  // "OFF", whitespace, then the counts on one line (as CGAL: the edge count unused)
  if(text.size() < 4 || text.compare(0, 3, "OFF") != 0 || !(is_blank(text[3]) || text[3] == '\n'))
    return false;
  p += 3;
  skip_spaces();
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!read_line() || tokens.size() != 3 || !plain_OFF_integer(tokens[0], nv) || !plain_OFF_integer(tokens[1], nf) ||
     !plain_OFF_integer(tokens[2], ne) || nv == 0 || nf == 0 || p == end)
    return false;
  points.clear();
  polygons.clear();
  points.reserve((std::min)(nv, text.size()));
  polygons.reserve((std::min)(nf, text.size()));
  for(std::size_t i = 0; i < nv; ++i)
  {
    skip_spaces();
    std::array<double, 3> x;
    if(p == end || !read_line() || tokens.size() != 3 || !plain_OFF_number(tokens[0], x[0]) ||
       !plain_OFF_number(tokens[1], x[1]) || !plain_OFF_number(tokens[2], x[2]))
      return fail();
    points.emplace_back();
    CGAL::IO::internal::fill_point(x[0], x[1], x[2], 1.0, points.back());
  }
  for(std::size_t i = 0; i < nf; ++i)
  {
    skip_spaces();
    std::size_t n = 0;
    if(p == end || !read_line() || tokens.empty() || !plain_OFF_integer(tokens[0], n) || n < 3 || tokens.size() != n + 1)
      return fail();
    polygons.emplace_back(n);
    for(std::size_t k = 0; k < n; ++k)
      if(!plain_OFF_integer(tokens[k + 1], polygons.back()[k]) || polygons.back()[k] >= nv)
        return fail();
  }
  return true;
}

// Reads an OBJ file strictly. CGAL's OBJ reader silently drops a face token
// that is not a number ("f 1 2 x" gives a 2-gon) and maps the invalid index 0
// to a vertex defined later in the file: we run this parser on every OBJ file
// to reject such files, and use its soup to explain a file CGAL rejected.
template <class Point>
void parse_OBJ_strictly(const std::string& filename, std::vector<Point>& points,
                        std::vector<std::vector<std::size_t>>& polygons)
{
  // The statements CGAL 5.5's OBJ reader accepts and ignores.
  static const char* const ignored[] = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib",
    "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2",
    "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};

  Token_lines lines(filename);
  std::vector<std::string> tokens;
  auto where = [&] { return "line " + std::to_string(lines.line_number()) + ": "; };
  points.clear();
  polygons.clear();
  while(lines.next(tokens))
  {
    const std::string& s = tokens[0];
    if(s == "v")
    {
      if(tokens.size() < 4)
        file_error(filename, where() + "vertex " + std::to_string(points.size()) + " has " +
                               std::to_string(tokens.size() - 1) + " coordinate(s), expected 3");
      double c[3];
      for(int k = 0; k < 3; ++k)
        if(!parse_double(tokens[k + 1], c[k]))
          file_error(filename, where() + "vertex " + std::to_string(points.size()) + ": '" + tokens[k + 1] +
                                 "' is not a number");
      points.emplace_back(c[0], c[1], c[2]);
    }
    else if(s == "f")
    {
      polygons.emplace_back();
      for(std::size_t k = 1; k < tokens.size(); ++k)
      {
        // "i", "i/t", "i//n" or "i/t/n": only the vertex reference i matters.
        const std::string ref = tokens[k].substr(0, tokens[k].find('/'));
        long long i = 0;
        if(!parse_integer(ref, i) || i == 0)
          file_error(filename, where() + "face " + std::to_string(polygons.size() - 1) + ": '" + tokens[k] +
                                 "' is not a vertex reference (1-based, or negative for relative)");
        if(i < 0 && static_cast<long long>(points.size()) + i < 0)
          file_error(filename, where() + "face " + std::to_string(polygons.size() - 1) + ": relative reference " +
                                 tokens[k] + " points before the first vertex");
        // A positive reference may name a vertex defined further down the file;
        // one past the end is left to the validation (index out of range).
        polygons.back().push_back(i > 0 ? static_cast<std::size_t>(i - 1)
                                        : static_cast<std::size_t>(static_cast<long long>(points.size()) + i));
      }
    }
    else if(std::find(std::begin(ignored), std::end(ignored), s) == std::end(ignored))
      file_error(filename, where() + "unknown OBJ statement '" + s + "'");
  }
}

// Fails early, with the reason, on a directory or a file that cannot be opened.
inline void check_file_can_be_opened(const std::string& filename)
{
  std::error_code ec;
  if(std::filesystem::is_directory(filename, ec))
    file_error(filename, "is a directory, not a mesh file");
  errno = 0;
  std::ifstream probe(filename);
  if(!probe)
    file_error(filename, std::string("cannot open the file (") +
                           (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
}

// std::isspace of the C locale, which CGAL's readers skip between values
// (' ', or '\t' '\n' '\v' '\f' '\r', which follow each other)
inline bool is_space(char c) { return c == ' ' || static_cast<unsigned char>(c - '\t') < 5; }

// What operator>> of a number reads in libstdc++ (num_get), which CGAL's
// ASCII readers call (its iformat() too, for a double), whitespace skipped:
// the characters of `in` (peek(), -1 at the end, and next()) it takes.
//
// A float or a double: a sign, digits with one '.', an exponent ('e' after a
// digit, a sign, digits). False if they are no number (the read fails); an
// overflow fails too, but reads its characters all the same.
template <class Cursor>
bool read_float_characters(Cursor& in)
{
  int c = in.peek();
  if(c == '+' || c == '-') { in.next(); c = in.peek(); }
  bool digits = false, point = false;
  for(;; in.next(), c = in.peek())
  {
    if(c >= '0' && c <= '9') digits = true;
    else if(c == '.' && !point) point = true;
    else break;
  }
  if(!digits) return false;
  if(c != 'e' && c != 'E') return true;
  in.next();
  c = in.peek();
  if(c == '+' || c == '-') { in.next(); c = in.peek(); }
  bool exponent = false;
  for(; c >= '0' && c <= '9'; in.next(), c = in.peek()) exponent = true;
  return exponent;
}

// An integer: a sign, then decimal digits, all of them (also past an
// overflow, where `magnitude` saturates). False if there is no digit.
template <class Cursor>
bool read_integer_characters(Cursor& in, bool& negative, unsigned long long& magnitude, bool& overflow)
{
  int c = in.peek();
  negative = c == '-';
  if(c == '+' || c == '-') { in.next(); c = in.peek(); }
  magnitude = 0;
  overflow = false;
  bool digits = false;
  for(; c >= '0' && c <= '9'; in.next(), c = in.peek())
  {
    digits = true;
    if(magnitude > (std::numeric_limits<unsigned long long>::max() - 9) / 10) overflow = true;
    else magnitude = 10 * magnitude + static_cast<unsigned long long>(c - '0');
  }
  return digits;
}

// The characters [p, last) as a cursor of the functions above.
struct Characters
{
  const char* p;
  const char* last;
  int peek() const { return p != last ? static_cast<unsigned char>(*p) : -1; }
  void next() { ++p; }
};

// The counts a file announces, checked against its size before CGAL's
// readers allocate them (OFF_file_checks, PLY_file_checks).
class File_size_checks
{
protected:
  explicit File_size_checks(const std::string& filename) : filename_(filename)
  {
    std::error_code ec;
    size_ = std::filesystem::file_size(filename, ec);
    if(ec) size_ = 0;
  }

  [[noreturn]] void refuse(const std::string& announced, std::uintmax_t least) const
  {
    file_error(filename_, "the header announces " + announced + ", which take at least " + std::to_string(least) +
                            " bytes, but the file has " + std::to_string(size_) + ": refused before reading");
  }

  const std::string& filename_;
  std::uintmax_t size_ = 0; // 0: empty or unreadable (the readers say so)
};

} // namespace mesh_io
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_MESH_FILE_TEXT_H
