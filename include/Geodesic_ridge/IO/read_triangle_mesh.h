// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a triangle mesh from an OFF, OBJ or PLY file, keeping the file's
// vertex and face order, triangulating polygons (and repairing the mesh on
// request) with a map back to the file's indices, and turns every problem
// into a typed exception.
#ifndef GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H
#define GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/file_index_map.h>
#include <Geodesic_ridge/internal/ply_face_layouts.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/repair.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

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

// The body of a PLY file, from `offset` on, read in chunks of 1 MB (a buffer
// the size of the file would cost more than the walk over it, a fresh
// allocation's pages; the small reads of a stream, more still).
class Ply_body
{
public:
  Ply_body(const std::string& filename, std::uintmax_t offset, std::uintmax_t file_size)
    : in_(filename, std::ios::binary), buffer_(std::size_t(1) << 20), base_(offset), size_(file_size)
  {
    in_.seekg(static_cast<std::streamoff>(offset));
  }

  // The bytes of the file after the position.
  std::uintmax_t left() const
  {
    const std::uintmax_t at = base_ + pos_;
    return at < size_ ? size_ - at : 0;
  }

  // True if n bytes (at most 1 MB) are at data().
  bool ensure(std::size_t n)
  {
    while(end_ - pos_ < n)
      if(!refill(pos_)) return false;
    return true;
  }
  const char* data() const { return buffer_.data() + pos_; }

  void skip(std::uintmax_t n)
  {
    if(n <= end_ - pos_)
    {
      pos_ += static_cast<std::size_t>(n);
      return;
    }
    n -= end_ - pos_;
    base_ += end_;
    pos_ = end_ = 0;
    base_ += n;
    in_.seekg(static_cast<std::streamoff>(n), std::ios::cur);
  }

  // The next character, -1 at the end of the file.
  int peek()
  {
    if(pos_ == end_ && !refill(pos_)) return -1;
    return static_cast<unsigned char>(buffer_[pos_]);
  }
  void next() { ++pos_; }

private:
  // Keeps the bytes from `from` on, at the front, and reads after them; false
  // at the end of the file.
  bool refill(std::size_t from)
  {
    const std::size_t kept = end_ - from; // (a few bytes at most)
    std::memmove(buffer_.data(), buffer_.data() + from, kept);
    base_ += from;
    pos_ -= (std::min)(pos_, from);
    end_ = kept;
    if(!in_) return false;
    in_.read(buffer_.data() + kept, static_cast<std::streamsize>(buffer_.size() - kept));
    end_ += static_cast<std::size_t>(in_.gcount());
    return end_ > kept;
  }

  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0; // in buffer_
  std::uintmax_t base_;           // the file offset of buffer_[0]
  std::uintmax_t size_;
};

// The counts a header announces must fit in the file: CGAL's OFF reader
// reserves the announced vertices before reading one (a 40-byte file whose
// header announced 2e9 vertices ended in "out of memory"). Each element takes
// at least a few bytes: an ASCII OFF vertex "x y z\n" 6, a face "0\n" 2, a
// binary one 12 and 4; a PLY item, in binary, its scalar properties and its
// lists' counts, in ASCII 2 bytes per property (and no more items than
// bytes). A header that announces more than the file can hold is refused
// before anything is allocated. So is an OFF face or a PLY list whose size
// the rest of the file cannot hold: CGAL's readers resize it to that size
// before reading it.
class Header_counts
{
public:
  explicit Header_counts(const std::string& filename) : filename_(filename)
  {
    std::error_code ec;
    size_ = std::filesystem::file_size(filename, ec);
    if(ec) size_ = 0;
  }

  void check(Mesh_file_format format) const
  {
    if(size_ == 0) return; // (an empty or unreadable file: the readers say so)
    if(format == Mesh_file_format::OFF) check_OFF();
    else if(format == Mesh_file_format::PLY) check_PLY();
  }

  // The face sizes of an OFF file, as CGAL's reader reads them: a walk over
  // the whole file, so only for the files that go to that reader
  // (`read_plain_OFF()` checks its own).
  void check_OFF_faces() const
  {
    std::ifstream in(filename_, std::ios::binary);
    CGAL::File_header_OFF header(false);
    std::uintmax_t start = 0;
    if(size_ == 0 || !read_OFF_header(in, header, start) || start >= size_) return;
    in.clear();
    in.seekg(0);
    std::string text(static_cast<std::size_t>(size_), '\0');
    in.read(&text[0], static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if(start >= text.size()) return;
    if(header.binary())
      check_binary_OFF_faces(header, text, static_cast<std::size_t>(start));
    else
      check_ascii_OFF_faces(header, text, static_cast<std::size_t>(start));
  }

private:
  [[noreturn]] void refuse(const std::string& announced, std::uintmax_t least) const
  {
    file_error(filename_, "the header announces " + announced + ", which take at least " + std::to_string(least) +
                            " bytes, but the file has " + std::to_string(size_) + ": refused before reading");
  }

  // OFF and its variants (COFF, NOFF, ..., binary)
  void check_OFF() const
  {
    check_OFF_counts_line();
    // then the counts as CGAL's reader reads them, which the line above may
    // not hold: they may span lines, or be binary (after "BINARY")
    std::ifstream in(filename_, std::ios::binary);
    CGAL::File_header_OFF header(false);
    std::uintmax_t start = 0;
    if(!read_OFF_header(in, header, start)) return;
    const long double nv = static_cast<long double>(header.size_of_vertices()),
                      nf = static_cast<long double>(header.size_of_facets());
    const long double least = header.binary() ? OFF_binary_vertex_bytes(header) * nv + 4.0L * nf
                                              : 6.0L * nv + 2.0L * nf;
    const std::uintmax_t room = header.binary() ? size_ - (std::min)(size_, start) : size_;
    if(least > static_cast<long double>(room))
      refuse(std::to_string(header.size_of_vertices()) + " vertices and " + std::to_string(header.size_of_facets()) +
               " faces",
             static_cast<std::uintmax_t>((std::min)(least + (size_ - room), 1.8e19L)));
  }

  // "OFF" (or a variant) and "V F E" on the next line or on the keyword's
  void check_OFF_counts_line() const
  {
    Token_lines lines(filename_);
    std::vector<std::string> t;
    if(!lines.next(t) || t[0].size() < 3 || t[0].compare(t[0].size() - 3, 3, "OFF") != 0) return;
    if(t[0].size() > 3 && t[0][t[0].size() - 4] == 'n') return; // (nOFF: the dimension comes first)
    if(t.size() > 1) t.erase(t.begin());
    else if(!lines.next(t)) return;
    long long nv = 0, nf = 0;
    if(t.size() < 2 || !parse_integer(t[0], nv) || !parse_integer(t[1], nf) || nv < 0 || nf < 0) return;
    const long double least = 6.0L * nv + 2.0L * nf;
    if(!(least > static_cast<long double>(size_))) return;
    // the line-by-line diagnosis allocates only what is there and names
    // where the file ends (it throws: the file cannot hold the counts)
    std::vector<CGAL::Epick::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    diagnose_OFF(filename_, points, polygons);
    refuse(std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces",
           static_cast<std::uintmax_t>((std::min)(least, 1.8e19L)));
  }

  // The header as CGAL's OFF reader reads it (File_header_OFF, its parser);
  // false if that fails. `start` is where it stops. (That reader reads the
  // items of SKEL and nOFF files as those of OFF.)
  bool read_OFF_header(std::ifstream& in, CGAL::File_header_OFF& header, std::uintmax_t& start) const
  {
    in >> header;
    if(!in) return false;
    const std::streamoff position = in.tellg(); // (-1 at the end of the file)
    start = position < 0 ? size_ : static_cast<std::uintmax_t>(position);
    return true;
  }

  // A vertex of a binary OFF file as CGAL's reader reads it: the point, its
  // normal (NOFF) and its texture coordinates (ST), 4-byte floats, one more
  // each in a homogeneous (4OFF) file; no color.
  static int OFF_binary_vertex_bytes(const CGAL::File_header_OFF& header)
  {
    const int w = header.is_homogeneous() ? 1 : 0;
    return 4 * (3 + w + (header.has_normals() ? 3 + w : 0) + (header.has_textures() ? 2 + w : 0));
  }

  // CGAL's ASCII OFF scanner reads each vertex and each face from the next
  // line that is neither blank nor a '#' comment. A face's size is the first
  // number of its line, read as a double (operator>>) and converted to
  // size_t; the face is resized to it before its indices are read (-8 or
  // 1e121: a huge size).
  //
  // With colors (COFF) or texture coordinates (ST), the scanner reads them
  // at indices it derives from the count of numbers on the line, and on the
  // lines before, without checking them (found by fuzz/): a line it would
  // read out of bounds is refused as well. So is a homogeneous vertex (4OFF)
  // of w = 0, on which CGAL's reader asserts.
  void check_ascii_OFF_faces(const CGAL::File_header_OFF& header, const std::string& text, std::size_t p) const
  {
    const std::size_t n = text.size();
    const auto header_end = text.begin() + static_cast<std::ptrdiff_t>(p);
    std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), header_end, '\n'));
    std::size_t first = 0, last = 0, first_line = 0;
    // the line CGAL's scanner reads next is [first, last), line `first_line`
    auto next_line = [&]() {
      for(;;)
      {
        while(p < n && is_space(text[p]))
          line += text[p++] == '\n' ? 1 : 0;
        if(p == n) return false;
        first = p;
        first_line = line;
        const std::size_t eol = text.find('\n', p);
        last = eol == std::string::npos ? n : eol;
        p = eol == std::string::npos ? n : eol + 1;
        line += eol == std::string::npos ? 0 : 1;
        if(text[first] != '#') return true;
      }
    };
    auto where = [&] { return "line " + std::to_string(first_line) + ": "; };
    std::string number;
    // the numbers of the line as the scanner reads them (operator>> up to the
    // first that fails, an overflow too)
    std::vector<double> numbers;
    auto read_numbers = [&] {
      numbers.clear();
      Characters c{text.data() + first, text.data() + last};
      for(;;)
      {
        while(c.peek() != -1 && is_space(static_cast<char>(c.peek()))) c.next();
        const char* const start = c.p;
        if(c.peek() == -1 || !read_float_characters(c)) return;
        number.assign(start, c.p);
        const double x = std::strtod(number.c_str(), nullptr);
        if(std::isinf(x)) return;
        numbers.push_back(x);
      }
    };
    // scan_color(): one number, an index in a color table (an int; the table
    // is read before it if negative), or three
    auto check_color = [&](std::size_t at, std::size_t values, const std::string& item) {
      if(values >= 3 || (values == 1 && numbers[at] > -1 && numbers[at] < 2147483648.0)) return;
      file_error(filename_, where() + item + " has " + std::to_string(values) +
                              " color value(s) after one with colors: CGAL's reader takes 3 or 4, or 1 (a color index, "
                              "not negative), and reads out of bounds otherwise");
    };
    const bool colors = header.has_colors(), textures = header.has_textures(), w = header.is_homogeneous();
    const std::size_t h = w ? 1 : 0, color_at = 3 + h + (header.has_normals() ? 3 + h : 0);
    const std::size_t need = color_at + (textures ? 2 + h : 0);
    const std::size_t nv = header.size_of_vertices();
    if(textures && !colors && nv > 0)
      file_error(filename_, "texture coordinates without colors (ST but no C in the OFF keyword): CGAL's reader reads "
                            "them at an uninitialized index");
    bool vertex_colors = false, face_colors = false;
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(!next_line())
      {
        if(!colors) return; // (CGAL's reader fails on the missing vertex)
        file_error(filename_, "file is truncated: the header announces " + std::to_string(nv) +
                                " vertices, but it ends after " + std::to_string(i));
      }
      if(!colors && !w) continue;
      read_numbers();
      if(w && numbers.size() >= 4 && numbers[3] == 0)
        file_error(filename_, where() + "vertex " + std::to_string(i) + " has the homogeneous coordinate w = 0");
      if(!colors) continue;
      if(numbers.size() < need)
        file_error(filename_, where() + "vertex " + std::to_string(i) + " has " + std::to_string(numbers.size()) +
                                " number(s), expected " + std::to_string(need) + " at least");
      const std::size_t values = numbers.size() - need;
      vertex_colors = vertex_colors || values != 0;
      if(vertex_colors) check_color(color_at, values, "vertex " + std::to_string(i));
    }
    for(std::size_t j = 0; j < header.size_of_facets(); ++j)
    {
      if(!next_line()) return; // (CGAL's reader reads an empty face, then fails)
      // (the line ends at a '#', where no number goes on)
      Characters line_characters{text.data() + first, text.data() + n};
      if(!read_float_characters(line_characters)) return; // (CGAL's reader fails there)
      const std::size_t q = static_cast<std::size_t>(line_characters.p - text.data());
      number.assign(text, first, q - first);
      const double size = std::strtod(number.c_str(), nullptr);
      if(std::isinf(size)) return; // (operator>> fails on an overflow: CGAL's reader fails there)
      // each index takes 2 bytes at least (" 0")
      if(size > -1 && size < static_cast<double>((n - q) / 2) + 1)
      {
        if(!colors) continue;
        read_numbers();
        const std::size_t k = static_cast<std::size_t>(size);
        if(numbers.size() < k + 1) return; // (CGAL's reader fails on a missing index, before the color)
        for(std::size_t m = 1; m <= k; ++m)
          if(!(numbers[m] > -1 && numbers[m] < static_cast<double>(nv))) return; // (and on an index out of range)
        const std::size_t values = numbers.size() - k - 1;
        face_colors = face_colors || values != 0;
        if(face_colors) check_color(k + 1, values, "face " + std::to_string(j));
        continue;
      }
      // the line-by-line diagnosis of an "OFF" file says what is wrong on
      // the line, as for the files CGAL's reader refuses (it allocates only
      // what is there, and throws: the face is not what it announces)
      std::vector<CGAL::Epick::Point_3> points;
      std::vector<std::vector<std::size_t>> polygons;
      diagnose_OFF(filename_, points, polygons);
      file_error(filename_, where() + "face " + std::to_string(j) + " announces " + text.substr(first, q - first) +
                              " vertices, " +
                              (size <= -1 ? std::string("a negative count")
                                          : "which the file cannot hold (" + std::to_string(n - q) +
                                              " bytes left, at least 2 per index)"));
    }
  }

  // CGAL's binary OFF scanner reads a face's size (a big-endian int32) and
  // resizes the face to it, also when the file ended before it (from
  // uninitialized memory). It asserts on a homogeneous vertex (4OFF) of w = 0,
  // also one the file ends in.
  void check_binary_OFF_faces(const CGAL::File_header_OFF& header, const std::string& text, std::size_t p) const
  {
    const std::size_t n = text.size();
    const std::size_t vertex = static_cast<std::size_t>(OFF_binary_vertex_bytes(header));
    const std::size_t nv = header.size_of_vertices();
    if(nv > (n - p) / vertex)
    {
      if(!header.is_homogeneous()) return; // (CGAL's reader fails in the vertices)
      file_error(filename_, "binary OFF: file is truncated: the header announces " + std::to_string(nv) +
                              " vertices, but it ends after " + std::to_string((n - p) / vertex));
    }
    auto int32_at = [&](std::size_t at) {
      std::uint32_t bits = 0;
      for(int k = 0; k < 4; ++k)
        bits = (bits << 8) | static_cast<unsigned char>(text[at + k]);
      return bits;
    };
    for(std::size_t i = 0; header.is_homogeneous() && i < nv; ++i)
      if((int32_at(p + vertex * i + 12) & 0x7fffffffu) == 0) // (w, the 4th float: +0 or -0)
        file_error(filename_, "binary OFF: vertex " + std::to_string(i) + " has the homogeneous coordinate w = 0");
    p += vertex * nv;
    for(std::size_t j = 0; j < header.size_of_facets(); ++j)
    {
      const std::size_t at = p;
      auto where = [&] { return "binary OFF, byte " + std::to_string(at) + ": face " + std::to_string(j); };
      if(n - p < 4)
        file_error(filename_, where() + ": the file ends before its vertex count");
      const std::uint32_t bits = int32_at(p);
      const std::int64_t size = bits < 0x80000000u ? std::int64_t(bits) : std::int64_t(bits) - (std::int64_t(1) << 32);
      p += 4;
      if(size == -1) return; // (CGAL's reader stops there)
      if(size < 0)
        file_error(filename_, where() + " announces " + std::to_string(size) + " vertices, a negative count");
      if(static_cast<std::size_t>(size) > (n - p) / 4)
        file_error(filename_, where() + " announces " + std::to_string(size) +
                                " vertices, which the file cannot hold (" + std::to_string(n - p) +
                                " bytes left, 4 per index)");
      p += 4 * static_cast<std::size_t>(size);
    }
  }

  // A PLY scalar type as CGAL's reader knows it: its size in bytes, 0 for a
  // type it does not know (it then drops the property, and reads none of it).
  struct Ply_type
  {
    int bytes = 0;
    bool is_float = false, is_signed = false;
  };

  static Ply_type ply_type(const std::string& type)
  {
    auto make = [](int bytes, bool is_float, bool is_signed) {
      Ply_type t;
      t.bytes = bytes;
      t.is_float = is_float;
      t.is_signed = is_signed;
      return t;
    };
    if(type == "char" || type == "int8") return make(1, false, true);
    if(type == "uchar" || type == "uint8") return make(1, false, false);
    if(type == "short" || type == "int16") return make(2, false, true);
    if(type == "ushort" || type == "uint16") return make(2, false, false);
    if(type == "int" || type == "int32") return make(4, false, true);
    if(type == "uint" || type == "uint32") return make(4, false, false);
    if(type == "float" || type == "float32") return make(4, true, true);
    if(type == "double" || type == "float64") return make(8, true, true);
    return Ply_type();
  }

  struct Ply_property
  {
    std::string name;
    Ply_type type; // of a list: its items'
    bool list = false;
    Ply_type count; // of a list
  };

  struct Ply_element
  {
    std::string name;
    std::size_t count = 0;                 // read as CGAL's reader does: "-1" is SIZE_MAX
    long double least = 0;                 // bytes per item
    std::vector<Ply_property> properties;  // those CGAL's reader reads
  };

  void check_PLY() const
  {
    std::ifstream in(filename_, std::ios::binary);
    std::string line;
    bool binary = false, ply = false, readable = true, ended = false;
    int format = -1; // 0 ASCII, 1 little-endian, 2 big-endian, -1 none CGAL's reader knows
    std::vector<Ply_element> elements;
    std::uintmax_t header = 0;
    int lines = 0;
    for(; lines < 100000 && std::getline(in, line); ++lines)
    {
      header += line.size() + 1;
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if(lines == 0)
      {
        ply = keyword == "ply";
        continue;
      }
      if(lines == 1)
      {
        // CGAL's reader takes the format from the second line, whatever its
        // first word (an "element" there is none; found by fuzz/)
        std::string f, version;
        readable = static_cast<bool>(words >> f >> version);
        format = f == "ascii" ? 0 : f == "binary_little_endian" ? 1 : f == "binary_big_endian" ? 2 : -1;
        binary = f != "ascii";
        continue;
      }
      if(keyword.empty())
        readable = false; // (CGAL's reader fails on an empty header line)
      else if(keyword == "element")
      {
        Ply_element e;
        if(!(words >> e.name >> e.count)) return; // (CGAL's reader says what is wrong)
        elements.push_back(e);
      }
      else if(keyword == "property" && elements.empty())
        // CGAL's reader adds a property to its last element, and has none
        // yet: it would read out of bounds (found by fuzz/)
        file_error(filename_, "PLY header: a property before any element (line " + std::to_string(lines + 1) + ")");
      else if(keyword == "property")
      {
        std::string type, name;
        words >> type >> name;
        Ply_property p;
        if(type == "list") // "list COUNT ITEM NAME"; CGAL's reader takes integer counts only
        {
          std::string item;
          words >> item >> p.name;
          if(ply::is_vertex_element(elements.back().name) && (p.name == "x" || p.name == "y" || p.name == "z"))
            // (as below: CGAL's point reader asserts on it; found by fuzz/)
            file_error(filename_, "PLY header: vertex coordinate '" + p.name +
                                    "' is a list, not float or double (line " + std::to_string(lines + 1) + ")");
          p.list = true;
          p.count = ply_type(name);
          p.type = ply_type(item);
          if(p.count.is_float) p.count.bytes = 0;
        }
        else
        {
          if(ply::is_vertex_element(elements.back().name) && (name == "x" || name == "y" || name == "z") &&
             type != "float" && type != "float32" && type != "double" && type != "float64")
            // CGAL's point reader asserts (and without assertions dereferences
            // null) on an integer coordinate (found by fuzz/)
            file_error(filename_, "PLY header: vertex coordinate '" + name + "' is '" + type +
                                    "', not float or double (line " + std::to_string(lines + 1) + ")");
          p.name = name;
          p.type = ply_type(type);
        }
        if(p.name.empty())
          readable = false; // (CGAL's reader fails on it)
        else if(p.type.bytes != 0 && (!p.list || p.count.bytes != 0))
        {
          elements.back().least += binary ? (p.list ? p.count.bytes : p.type.bytes) : 2;
          elements.back().properties.push_back(p);
        }
      }
      else if(keyword == "end_header")
      {
        ended = true;
        break;
      }
    }
    if(!ended)
    {
      // CGAL's reader takes the whole file as the header, then reads the
      // items from the failed stream: a list sized from uninitialized memory
      if(ply && lines < 100000)
        file_error(filename_, "malformed or truncated PLY header: no 'end_header' line");
      return;
    }
    long double least = 0;
    std::string announced;
    bool absurd = false;
    const std::uintmax_t body = (std::min)(size_, header);
    for(const Ply_element& e : elements)
    {
      least += e.least * e.count;
      announced += (announced.empty() ? "" : ", ") + std::to_string(e.count) + " '" + e.name + "'";
      // items of no property CGAL's reader knows take none of the bytes it
      // reads, but it loops over them (and adds a point for each vertex item):
      // more of them than the file has bytes is refused too
      absurd = absurd || (e.least == 0 && e.count > size_);
    }
    if(absurd)
      file_error(filename_, "the header announces " + announced + ", more items than the file has bytes (" +
                              std::to_string(size_) + "): refused before reading");
    // (in ASCII the last value needs no separator after it)
    if(least > static_cast<long double>(size_ - body) + (binary ? 0 : 1))
      refuse(announced, static_cast<std::uintmax_t>((std::min)(least + header, 1.8e19L)));
    if(ply && readable && format >= 0)
      check_PLY_lists(elements, format, body);
  }

  // The integer CGAL's ASCII PLY reader reads, a list's count or a value:
  // operator>> of its type (of short or unsigned short for a char, then
  // narrowed, 0 if that fails), which saturates on an overflow (and fails),
  // and negates an unsigned value modulo its range.
  struct Ascii_integer
  {
    bool digits = false; // false: the reader reads 0 and fails
    bool ok = false;     // the read does not fail
    long long value = 0;
  };

  static Ascii_integer ascii_integer(Ply_body& body, const Ply_type& type)
  {
    Ascii_integer r;
    bool negative = false, fail = false;
    unsigned long long magnitude = 0;
    if(!read_integer_characters(body, negative, magnitude, fail)) return r;
    r.digits = true;
    const int bits = 8 * (type.bytes == 1 ? 2 : type.bytes);
    const unsigned long long max = type.is_signed ? (1ULL << (bits - 1)) - 1 : (1ULL << bits) - 1;
    long long value = 0;
    if(type.is_signed)
    {
      if(fail || magnitude > max + (negative ? 1 : 0))
      {
        fail = true;
        value = negative ? -static_cast<long long>(max) - 1 : static_cast<long long>(max);
      }
      else
        value = negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
    }
    else if(fail || magnitude > max)
    {
      fail = true;
      value = static_cast<long long>(max);
    }
    else
      value = static_cast<long long>(negative && magnitude != 0 ? max + 1 - magnitude : magnitude);
    if(type.bytes == 1)
      value = fail ? 0 : type.is_signed ? static_cast<signed char>(value) : static_cast<unsigned char>(value);
    r.value = value;
    r.ok = !fail;
    return r;
  }

  // Reads a value as CGAL's ASCII PLY reader does; false where that fails (a
  // float that overflows passes: the walk goes on, at worst refusing a file
  // that reader refuses)
  static bool ascii_value(Ply_body& body, const Ply_type& type)
  {
    return type.is_float ? read_float_characters(body) : ascii_integer(body, type).ok;
  }

  [[noreturn]] void refuse_list(const Ply_element& e, std::size_t item, const std::string& what) const
  {
    file_error(filename_, "malformed or truncated PLY: element '" + e.name + "' item " + std::to_string(item) + ": " +
                            what);
  }

  // (CGAL's reader converts a negative count to a huge size_t)
  void check_list_count(const Ply_element& e, std::size_t item, const Ply_property& p, long long count,
                        std::uintmax_t left, bool ascii) const
  {
    // (count < 2^32: no overflow)
    const std::uintmax_t per_value = static_cast<std::uintmax_t>(ascii ? 2 : p.type.bytes);
    if(count >= 0 && static_cast<std::uintmax_t>(count) * per_value <= left) return;
    refuse_list(e, item, "list '" + p.name + "' announces " + std::to_string(count) +
                           " values, which the file cannot hold (" +
                           (count < 0 ? std::string("a negative count")
                                      : std::to_string(left) + " bytes left, " +
                                          (ascii ? std::string("at least 2") : std::to_string(p.type.bytes)) +
                                          " per value") +
                           ")");
  }

  // CGAL's PLY reader (PLY_read_typed_list_with_typed_size::get) resizes a
  // list to the count the file gives before it reads an item of it, and takes
  // the count from uninitialized memory where the file ends. This walks the
  // body as that reader does, item by item, and refuses a list the rest of
  // the file cannot hold. Where the reader fails on its own (a value that is
  // not a number, the file ending in a scalar), the walk stops: the reader
  // reports it.
  void check_PLY_lists(const std::vector<Ply_element>& elements, int format, std::uintmax_t offset) const
  {
    std::size_t stop = 0; // (nothing to check after the last list)
    for(std::size_t i = 0; i < elements.size(); ++i)
      for(const Ply_property& p : elements[i].properties)
        if(p.list && elements[i].count > 0) stop = i + 1;
    if(stop == 0) return;
    Ply_body body(filename_, offset, size_);
    for(std::size_t i = 0; i < stop; ++i)
    {
      const Ply_element& e = elements[i];
      if(e.properties.empty()) continue;
      if(format == 0 ? !walk_ascii(body, e) : !walk_binary(body, e, format == 2)) return;
    }
  }

  // false where the walk stops
  bool walk_ascii(Ply_body& body, const Ply_element& e) const
  {
    // (operator>> skips whitespace first; at the end of the file it fails,
    // leaving the value it reads uninitialized)
    auto at_value = [&] {
      int c = body.peek();
      for(; c != -1 && is_space(static_cast<char>(c)); c = body.peek()) body.next();
      return c != -1;
    };
    for(std::size_t j = 0; j < e.count; ++j)
      for(const Ply_property& q : e.properties)
      {
        if(!q.list)
        {
          if(!at_value() || !ascii_value(body, q.type)) return false;
          continue;
        }
        if(!at_value()) refuse_list(e, j, "the file ends before the count of list '" + q.name + "'");
        const Ascii_integer count = ascii_integer(body, q.count);
        if(!count.digits) return false;
        check_list_count(e, j, q, count.value, body.left(), true);
        if(!count.ok) return false;
        for(long long k = 0; k < count.value; ++k)
        {
          if(!at_value())
            refuse_list(e, j, "list '" + q.name + "' announces " + std::to_string(count.value) +
                                " values, which the file cannot hold (it ends after " + std::to_string(k) + ")");
          if(!ascii_value(body, q.type)) return false;
        }
      }
    return true;
  }

  bool walk_binary(Ply_body& body, const Ply_element& e, bool big_endian) const
  {
    std::uintmax_t fixed = 0; // the bytes of an item without lists
    bool lists = false;
    for(const Ply_property& q : e.properties)
    {
      fixed += static_cast<std::uintmax_t>(q.type.bytes);
      lists = lists || q.list;
    }
    if(!lists)
    {
      if(e.count > body.left() / fixed) return false; // (CGAL's reader fails there)
      body.skip(fixed * e.count);
      return true;
    }
    for(std::size_t j = 0; j < e.count; ++j)
      for(const Ply_property& q : e.properties)
      {
        if(!q.list)
        {
          if(body.left() < static_cast<std::uintmax_t>(q.type.bytes)) return false;
          body.skip(static_cast<std::uintmax_t>(q.type.bytes));
          continue;
        }
        const int n = q.count.bytes;
        if(!body.ensure(static_cast<std::size_t>(n)))
          refuse_list(e, j, "the file ends before the count of list '" + q.name + "'");
        const unsigned char* b = reinterpret_cast<const unsigned char*>(body.data());
        std::uint32_t bits = 0;
        for(int k = 0; k < n; ++k)
          bits |= std::uint32_t(b[big_endian ? n - 1 - k : k]) << (8 * k);
        const std::uint32_t sign = std::uint32_t(1) << (8 * n - 1);
        const long long count = static_cast<long long>(bits) -
                                (q.count.is_signed && (bits & sign) ? 2 * static_cast<long long>(sign) : 0);
        body.skip(static_cast<std::uintmax_t>(n));
        check_list_count(e, j, q, count, body.left(), false);
        body.skip(static_cast<std::uintmax_t>(count) * static_cast<std::uintmax_t>(q.type.bytes));
      }
    return true;
  }

  const std::string& filename_;
  std::uintmax_t size_ = 0;
};

// Runs f; an `Invalid_mesh_error` it throws is thrown again, of the same type,
// with the file name in front of its message.
template <class F>
auto with_file_name(const std::string& filename, F&& f)
{
  try
  {
    return f();
  }
  catch(const Repairable_mesh_error& e)
  {
    throw Repairable_mesh_error(filename + ": " + e.what());
  }
  catch(const Invalid_mesh_error& e)
  {
    throw Invalid_mesh_error(filename + ": " + e.what());
  }
}

// Throws for a file CGAL's reader rejected: the validation's error if our own
// parse of the file (`have_soup`) has an index out of range or a non-finite
// coordinate, else a generic syntax error.
template <class Point>
[[noreturn]] void report_rejected_file(const std::string& filename, Mesh_file_format format, bool have_soup,
                                       const std::vector<Point>& points,
                                       const std::vector<std::vector<std::size_t>>& polygons)
{
  if(have_soup)
    with_file_name(filename, [&] {
      validation::Triangle_soup_validator<Point, std::vector<std::size_t>>(points, polygons).run_polygon_rules(false);
    });
  const char* name = format == Mesh_file_format::OFF ? "OFF" : format == Mesh_file_format::OBJ ? "OBJ" : "PLY";
  file_error(filename, std::string("malformed or truncated ") + name +
                         " content (CGAL's reader rejected it: a value that is not a number, a missing"
                         " value, or fewer elements than the header announces)");
}

// Reads the soup with CGAL's reader and throws `Mesh_file_error` (or, for a
// file CGAL rejected because of an out-of-range index or a NaN, the
// validation's `Invalid_mesh_error`) when it cannot be read entirely.
template <class Point>
void read_polygon_soup_or_throw(const std::string& filename, std::vector<Point>& points,
                                std::vector<std::vector<std::size_t>>& polygons)
{
  const Mesh_file_format format = mesh_file_format(filename);
  check_file_can_be_opened(filename);
  const Header_counts counts(filename);
  counts.check(format);

  std::vector<Point> strict_points;
  std::vector<std::vector<std::size_t>> strict_polygons;
  if(format == Mesh_file_format::OBJ)
    parse_OBJ_strictly(filename, strict_points, strict_polygons);

  points.clear();
  polygons.clear();
  if(format == Mesh_file_format::PLY && ply::needs_own_reader(filename))
  {
    try
    {
      ply::read(filename, points, polygons); // triangle strips, or 8- and 16-bit indices
    }
    catch(const std::length_error&)
    {
      // (CGAL's list reader, which it calls, sizes a list from the file: a
      // count the walk of Header_counts let through)
      file_error(filename, "malformed or truncated PLY content: a list size the reader cannot allocate");
    }
    catch(const std::bad_alloc&)
    {
      file_error(filename, "malformed or truncated PLY content: a list size the reader cannot allocate");
    }
    return;
  }
  if(format == Mesh_file_format::OFF && read_plain_OFF(filename, points, polygons))
    return;
  if(format == Mesh_file_format::OFF)
    counts.check_OFF_faces();
  // verbose(false): some of CGAL's readers print to std::cerr by default; we
  // report through the exception only.
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_soup(filename, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(const std::length_error&)
  {
    // CGAL's OFF scanner resizes a face to its announced size, which a
    // negative count ("-8") turns into a huge size_t (found by fuzz/): a
    // malformed file, diagnosed below like any other that CGAL refuses
  }
  catch(const std::bad_alloc&)
  {
  }
  if(read)
    return; // CGAL's OFF and PLY readers fail on a truncated file (checked), so the soup is complete.

  // CGAL failed: explain why as precisely as we can. On failure its soup may hold
  // uninitialized points, so it is dropped.
  points.clear();
  polygons.clear();
  bool have_soup = false;
  if(format == Mesh_file_format::OBJ)
  {
    strict_points.swap(points);
    strict_polygons.swap(polygons);
    have_soup = true;
  }
  else if(format == Mesh_file_format::OFF)
    have_soup = diagnose_OFF(filename, points, polygons);
  else
  {
    std::ifstream in(filename, std::ios::binary);
    std::string magic;
    std::getline(in, magic);
    if(magic.compare(0, 3, "ply") != 0)
      file_error(filename, "does not start with 'ply': not a PLY file");
  }
  report_rejected_file(filename, format, have_soup, points, polygons);
}

} // namespace mesh_io
} // namespace internal

namespace internal {
namespace mesh_io {

// The default visitor of `read_triangle_mesh()`: nothing to do.
struct Default_read_visitor
{
  void after_repair(const Repair_statistics&) const {}
};

// The number of points at the position of an earlier point.
template <class Point>
std::size_t count_repeated_positions(const std::vector<Point>& points)
{
  std::vector<validation::Epick_point_3> sorted;
  sorted.reserve(points.size());
  for(const Point& p : points)
    sorted.push_back(validation::to_epick(p));
  std::sort(sorted.begin(), sorted.end());
  std::size_t n = 0;
  for(std::size_t i = 1; i < sorted.size(); ++i)
    n += sorted[i] == sorted[i - 1] ? 1 : 0;
  return n;
}

// Validates the soup, its messages in the file's indices, keeping every
// connected component (the algorithm takes the source's). After the repair,
// what is left is no longer repairable.
template <class Point>
void validate(const Repaired_soup<Point>& soup, bool repaired)
{
  validation::Triangle_soup_validator<Point, std::array<std::size_t, 3>> validator(soup.points, soup.triangles);
  validator.set_file_indices(&soup.vertex_to_file, &soup.face_to_file);
  validator.allow_several_components();
  try
  {
    validator.run();
  }
  catch(const Repairable_mesh_error& e)
  {
    if(repaired)
      throw Invalid_mesh_error(std::string(e.what()) + " (left by the repair)");
    throw;
  }
}

// Builds tm from the soup, in its order; returns the descriptors of its
// vertices and faces. The soup is a valid closed manifold triangle mesh, so
// Euler::add_face cannot fail whatever the face order; if it does, it is a
// bug here or in the validation.
template <class TriangleMesh, class Point>
std::pair<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>,
          std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
build_mesh(const std::string& filename, const Repaired_soup<Point>& soup, TriangleMesh& tm)
{
  using GT = boost::graph_traits<TriangleMesh>;
  CGAL::clear(tm);
  auto vpm = get(CGAL::vertex_point, tm);
  std::pair<std::vector<typename GT::vertex_descriptor>, std::vector<typename GT::face_descriptor>> result;
  auto& vds = result.first;
  vds.reserve(soup.points.size());
  result.second.reserve(soup.triangles.size());
  // sized once (3F/2 edges on a closed mesh), not grown by doubling
  reserve(tm, static_cast<typename GT::vertices_size_type>(soup.points.size()),
          static_cast<typename GT::edges_size_type>((3 * soup.triangles.size() + 1) / 2),
          static_cast<typename GT::faces_size_type>(soup.triangles.size()));
  for(const Point& p : soup.points)
  {
    vds.push_back(add_vertex(tm));
    put(vpm, vds.back(), p);
  }
  for(std::size_t j = 0; j < soup.triangles.size(); ++j)
  {
    const auto& t = soup.triangles[j];
    const std::array<typename GT::vertex_descriptor, 3> corners = {vds[t[0]], vds[t[1]], vds[t[2]]};
    result.second.push_back(CGAL::Euler::add_face(corners, tm));
    if(result.second.back() == GT::null_face())
    {
      CGAL::clear(tm);
      throw Algorithm_error(filename + ": face " + std::to_string(soup.face_to_file[j]) +
                            " could not be added to the mesh although the mesh validated; please report this bug");
    }
  }
  return result;
}

} // namespace mesh_io
} // namespace internal

namespace IO {

/// \ingroup PkgGeodesicRidgeIO
///
/// \brief reads a triangle mesh (closed or with a border, in one or several parts) from an OFF, OBJ or PLY file,
/// triangulates its polygons, repairs it if asked to, checks it with
/// `validate_triangle_soup()`, and builds `tm` from it; returns the map from
/// `tm` back to the file's indices.
///
/// The format is chosen by the file extension (`.off`, `.obj`, `.ply`, in any
/// letter case) and the file is read with `CGAL::IO::read_polygon_soup()`;
/// a plain ASCII OFF file (the counts on one line, one vertex or face per
/// line, no comment, no color) is parsed by the package itself, to the same
/// soup, several times faster.
/// Faces with more than three vertices are triangulated with
/// `triangulate_polygons()` (\cgal's `triangulate_face()` rule); with
/// `parameters::repair(true)` the soup is repaired with `repair_mesh()`
/// instead, which triangulates too. Then the mesh is validated, and only then
/// is `tm` cleared and built: every failure is an exception, never a partial
/// mesh.
///
/// Every rule of `validate_triangle_soup()` is checked but rule 12: a mesh of
/// several connected components is read whole, and
/// `extract_connected_component()` copies the one the algorithm is to run on
/// (the source's). Without the repair, the vertices at the position of an
/// earlier vertex are counted (`Repair_statistics::repeated_positions`): the
/// surface is read open or in several parts there, which the repair would
/// merge.
///
/// Indices. Without polygons and without repair, vertex `i` and face `j` of
/// the file are the `i`-th vertex and the `j`-th face added to `tm` (for a
/// `CGAL::Surface_mesh`, vertex `i` and face `j`). With polygons, the first
/// triangle of file face `j` is face `j` and the polygons' other triangles come
/// after the file's faces. A repair renumbers both. In every case the
/// returned `File_index_map` maps vertices, faces and surface points between
/// `tm` and the file, and counts what changed (`File_index_map::statistics()`);
/// the validation's messages use the file's indices.
///
/// PLY: besides the `face` element that \cgal reads (32-bit index lists), the
/// function reads 8- and 16-bit index lists and triangle strips (element
/// `tristrips` with a `vertex_indices` list, -1 restarting a strip): file face
/// `j` is then the `j`-th face of the file's face and strip elements, in the
/// order of the file, a strip counting each of its triangles (the triangles
/// that repeat a vertex, which only join strips, are not faces). Any other
/// element that holds vertex-index lists is refused, naming the element.
///
/// Beyond \cgal's readers, the function
/// - checks the extension and that the file can be opened before reading;
/// - refuses, before anything is allocated, a header, an OFF face or a PLY
///   list that announces more elements than the rest of the file can hold
///   (\cgal's readers allocate what the file announces);
/// - re-reads an ASCII OFF file that \cgal rejected to name the line at fault
///   (a non-numeric token, a missing value, a truncation: the header announces
///   more vertices or faces than the file holds), and reports a NaN, infinite
///   or overflowing coordinate or an out-of-range index as the corresponding
///   validation error;
/// - parses every OBJ file strictly as well, because \cgal's OBJ reader
///   silently drops a non-numeric face token and maps the invalid index 0 to
///   a vertex defined later in the file.
///
/// Known leniencies kept from \cgal's readers: an OFF file with more face lines
/// than its header announces is read up to the announced count; an OFF face
/// index such as `1.7` is truncated to `1`; extra values at the end of an OFF
/// vertex or face line (colors) are ignored.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal
///         `CGAL::vertex_point` property map, e.g. `CGAL::Surface_mesh<Point_3>`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param filename the path of the file
/// \param tm the mesh to fill
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{repair}
///     \cgalParamDescription{whether the mesh is repaired with `repair_mesh()` (`Geodesic_ridge::parameters::repair`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{told what the triangulation and the repair changed, before the mesh is validated
///                           (so also when it is then refused): its member function
///                           `after_repair(const Geodesic_ridge::Repair_statistics&)` is called once}
///     \cgalParamType{a class with that member function}
///     \cgalParamDefault{a visitor that does nothing}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Mesh_file_error if the file cannot be opened, has an unsupported
///         extension, or its content is malformed or truncated; the message
///         names the file (and the line or the PLY element, when it can)
/// \throws Repairable_mesh_error if the mesh breaks a rule of
///         `validate_triangle_soup()` that `parameters::repair(true)` would fix
///         (only without it); the message starts with the file name
/// \throws Invalid_mesh_error if the mesh breaks another rule; the message
///         starts with the file name
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
File_index_map<TriangleMesh> read_triangle_mesh(const std::string& filename, TriangleMesh& tm,
                                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using VPM = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<VPM>::value_type;
  namespace mio = internal::mesh_io;
  const bool repair =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::repair_t()), false);
  const auto visitor = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::visitor),
                                                          mio::Default_read_visitor());

  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  mio::read_polygon_soup_or_throw(filename, points, polygons);
  Repaired_soup<Point> soup = mio::with_file_name(filename, [&] {
    return repair ? repair_mesh(points, polygons) : triangulate_polygons(points, polygons);
  });
  if(!repair)
    soup.statistics.repeated_positions = mio::count_repeated_positions(points);
  visitor.after_repair(soup.statistics);
  mio::with_file_name(filename, [&] { mio::validate(soup, repair); });
  auto descriptors = mio::build_mesh(filename, soup, tm);
  return File_index_map<TriangleMesh>(points, std::move(polygons), soup, std::move(descriptors.first),
                                      std::move(descriptors.second));
}

} // namespace IO

// Also reachable as Geodesic_ridge::read_triangle_mesh; IO:: is the spelling
// that follows CGAL (CGAL::IO::read_polygon_mesh).
using IO::read_triangle_mesh;

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H
