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

// The counts a header announces must fit in the file: CGAL's OFF reader
// reserves the announced vertices before reading one (a 40-byte file whose
// header announced 2e9 vertices ended in "out of memory"). Each element takes
// at least a few bytes: an ASCII OFF vertex "x y z\n" 6, a face "0\n" 2; a PLY
// item, in binary, its scalar properties and its lists' counts, in ASCII 2
// bytes per property. A header that announces more than the file can hold is
// refused before anything is allocated.
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

private:
  [[noreturn]] void refuse(const std::string& announced, std::uintmax_t least) const
  {
    file_error(filename_, "the header announces " + announced + ", which take at least " + std::to_string(least) +
                            " bytes, but the file has " + std::to_string(size_) + ": refused before reading");
  }

  // ASCII OFF and its variants (COFF, NOFF, ...): the keyword, then "V F E"
  void check_OFF() const
  {
    Token_lines lines(filename_);
    std::vector<std::string> t;
    if(!lines.next(t) || t[0].size() < 3 || t[0].compare(t[0].size() - 3, 3, "OFF") != 0) return;
    if(t.size() > 1) t.erase(t.begin());
    else if(!lines.next(t)) return;
    long long nv = 0, nf = 0;
    if(t.size() < 2 || !parse_integer(t[0], nv) || !parse_integer(t[1], nf) || nv < 0 || nf < 0) return;
    // (a binary OFF's counts come after "BINARY": not parsed, so not checked)
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

  static int scalar_bytes(const std::string& type)
  {
    if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
      return 4;
    if(type == "double" || type == "float64") return 8;
    return 0;
  }

  void check_PLY() const
  {
    std::ifstream in(filename_, std::ios::binary);
    std::string line;
    bool binary = false;
    struct Element { std::string name; long long count = 0; long double least = 0; };
    std::vector<Element> elements;
    std::uintmax_t header = 0;
    for(int lines = 0; std::getline(in, line) && lines < 100000; ++lines)
    {
      header += line.size() + 1;
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if(keyword == "format") { std::string f; words >> f; binary = f != "ascii"; }
      else if(keyword == "element")
      {
        Element e;
        if(!(words >> e.name >> e.count) || e.count < 0) return; // (CGAL's reader says what is wrong)
        elements.push_back(e);
      }
      else if(keyword == "property" && elements.empty())
        // CGAL's reader adds a property to its last element, and has none
        // yet: it would read out of bounds (found by fuzz/)
        file_error(filename_, "PLY header: a property before any element (line " + std::to_string(lines + 1) + ")");
      else if(keyword == "property")
      {
        std::string type;
        words >> type;
        if(type == "list") words >> type; // the count's type: at least the count is there
        else if(std::string name; ply::is_vertex_element(elements.back().name) && words >> name &&
                (name == "x" || name == "y" || name == "z") && type != "float" && type != "float32" &&
                type != "double" && type != "float64")
          // CGAL's point reader asserts (and without assertions dereferences
          // null) on an integer coordinate (found by fuzz/)
          file_error(filename_, "PLY header: vertex coordinate '" + name + "' is '" + type +
                                "', not float or double (line " + std::to_string(lines + 1) + ")");
        const int bytes = scalar_bytes(type);
        if(bytes == 0) return;
        elements.back().least += binary ? bytes : 2;
      }
      else if(keyword == "end_header")
      {
        long double least = 0;
        std::string announced;
        for(const Element& e : elements)
        {
          least += e.least * e.count;
          announced += (announced.empty() ? "" : ", ") + std::to_string(e.count) + " '" + e.name + "'";
        }
        if(least > static_cast<long double>(size_ - (std::min)(size_, header)))
          refuse(announced, static_cast<std::uintmax_t>((std::min)(least + header, 1.8e19L)));
        return;
      }
    }
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
  Header_counts(filename).check(format);

  std::vector<Point> strict_points;
  std::vector<std::vector<std::size_t>> strict_polygons;
  if(format == Mesh_file_format::OBJ)
    parse_OBJ_strictly(filename, strict_points, strict_polygons);

  points.clear();
  polygons.clear();
  if(format == Mesh_file_format::PLY && ply::needs_own_reader(filename))
  {
    ply::read(filename, points, polygons); // triangle strips, or 8- and 16-bit indices
    return;
  }
  if(format == Mesh_file_format::OFF && read_plain_OFF(filename, points, polygons))
    return;
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
