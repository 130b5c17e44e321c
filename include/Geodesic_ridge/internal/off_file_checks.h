// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks of an OFF file before CGAL's OFF reader reads it: the counts its
// header announces and the sizes of its faces must fit in the file, and its
// colors and homogeneous coordinates be what that reader can read.
#ifndef GEODESIC_RIDGE_INTERNAL_OFF_FILE_CHECKS_H
#define GEODESIC_RIDGE_INTERNAL_OFF_FILE_CHECKS_H

#include <Geodesic_ridge/internal/mesh_file_text.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF/File_header_OFF.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace mesh_io {

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
class OFF_file_checks : public File_size_checks
{
public:
  explicit OFF_file_checks(const std::string& filename) : File_size_checks(filename) {}

  // the vertex and face counts of the header
  void check_counts() const
  {
    if(size_ != 0) check_OFF();
  }

  // The face sizes of an OFF file, as CGAL's reader reads them: a walk over
  // the whole file, so only for the files that go to that reader
  // (`read_plain_OFF()` checks its own).
  void check_face_sizes() const
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
    Ascii_OFF_lines lines(text, p);
    if(textures_without_colors(header))
      file_error(filename_, "texture coordinates without colors (ST but no C in the OFF keyword): CGAL's reader reads "
                            "them at an uninitialized index");
    if(check_ascii_OFF_vertex_lines(header, lines))
      check_ascii_OFF_face_lines(header, lines);
  }

  static bool textures_without_colors(const CGAL::File_header_OFF& header)
  {
    return header.has_textures() && !header.has_colors() && header.size_of_vertices() > 0;
  }

  // The lines of an ASCII OFF file after its header, as CGAL's scanner reads them.
  struct Ascii_OFF_lines
  {
    const std::string& text;
    std::size_t p;              // where the scan goes on
    std::size_t line;           // the number of the line at p
    std::size_t first = 0, last = 0, first_line = 0; // the line read last: [first, last), its number
    std::vector<double> numbers; // its numbers (read_numbers())
    std::string number;          // the characters of one number (a buffer kept from line to line)

    Ascii_OFF_lines(const std::string& text, std::size_t p)
      : text(text), p(p), line(1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(p), '\n')))
    {}

    // the next line that is neither blank nor a comment; false at the end
    bool next()
    {
      const std::size_t n = text.size();
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
    }

    // the numbers of the line as the scanner reads them (operator>> up to the
    // first that fails, an overflow too)
    void read_numbers()
    {
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
    }

    std::string where() const { return "line " + std::to_string(first_line) + ": "; }
  };

  // scan_color(): one number, an index in a color table (an int; the table
  // is read before it if negative), or three
  void check_color(const Ascii_OFF_lines& lines, std::size_t at, std::size_t values, const std::string& item) const
  {
    if(values >= 3 || (values == 1 && lines.numbers[at] > -1 && lines.numbers[at] < 2147483648.0)) return;
    file_error(filename_, lines.where() + item + " has " + std::to_string(values) +
                            " color value(s) after one with colors: CGAL's reader takes 3 or 4, or 1 (a color index, "
                            "not negative), and reads out of bounds otherwise");
  }

  // the vertex lines: w != 0, and the colors where there are; false if CGAL's
  // reader fails on them (it says why)
  bool check_ascii_OFF_vertex_lines(const CGAL::File_header_OFF& header, Ascii_OFF_lines& lines) const
  {
    const bool colors = header.has_colors(), w = header.is_homogeneous();
    const std::size_t h = w ? 1 : 0, color_at = 3 + h + (header.has_normals() ? 3 + h : 0);
    const std::size_t need = color_at + (header.has_textures() ? 2 + h : 0);
    const std::size_t nv = header.size_of_vertices();
    bool vertex_colors = false;
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(!lines.next())
      {
        if(!colors) return false; // (CGAL's reader fails on the missing vertex)
        file_error(filename_, "file is truncated: the header announces " + std::to_string(nv) +
                                " vertices, but it ends after " + std::to_string(i));
      }
      if(!colors && !w) continue;
      lines.read_numbers();
      const std::vector<double>& numbers = lines.numbers;
      if(w && numbers.size() >= 4 && numbers[3] == 0)
        file_error(filename_, lines.where() + "vertex " + std::to_string(i) + " has the homogeneous coordinate w = 0");
      if(!colors) continue;
      if(numbers.size() < need)
        file_error(filename_, lines.where() + "vertex " + std::to_string(i) + " has " +
                                std::to_string(numbers.size()) + " number(s), expected " + std::to_string(need) +
                                " at least");
      const std::size_t values = numbers.size() - need;
      vertex_colors = vertex_colors || values != 0;
      if(vertex_colors) check_color(lines, color_at, values, "vertex " + std::to_string(i));
    }
    return true;
  }

  // the face lines: sizes the file can hold, and the colors where there are
  void check_ascii_OFF_face_lines(const CGAL::File_header_OFF& header, Ascii_OFF_lines& lines) const
  {
    const std::string& text = lines.text;
    const std::size_t n = text.size(), nv = header.size_of_vertices();
    bool face_colors = false;
    for(std::size_t j = 0; j < header.size_of_facets(); ++j)
    {
      if(!lines.next()) return; // (CGAL's reader reads an empty face, then fails)
      // (the line ends at a '#', where no number goes on)
      Characters line_characters{text.data() + lines.first, text.data() + n};
      if(!read_float_characters(line_characters)) return; // (CGAL's reader fails there)
      const std::size_t q = static_cast<std::size_t>(line_characters.p - text.data());
      const std::string number = text.substr(lines.first, q - lines.first);
      const double size = std::strtod(number.c_str(), nullptr);
      if(std::isinf(size)) return; // (operator>> fails on an overflow: CGAL's reader fails there)
      // each index takes 2 bytes at least (" 0")
      if(size > -1 && size < static_cast<double>((n - q) / 2) + 1)
      {
        if(!header.has_colors()) continue;
        lines.read_numbers();
        const std::vector<double>& numbers = lines.numbers;
        const std::size_t k = static_cast<std::size_t>(size);
        if(numbers.size() < k + 1) return; // (CGAL's reader fails on a missing index, before the color)
        for(std::size_t m = 1; m <= k; ++m)
          if(!(numbers[m] > -1 && numbers[m] < static_cast<double>(nv))) return; // (and on an index out of range)
        const std::size_t values = numbers.size() - k - 1;
        face_colors = face_colors || values != 0;
        if(face_colors) check_color(lines, k + 1, values, "face " + std::to_string(j));
        continue;
      }
      // the line-by-line diagnosis of an "OFF" file says what is wrong on
      // the line, as for the files CGAL's reader refuses (it allocates only
      // what is there, and throws: the face is not what it announces)
      std::vector<CGAL::Epick::Point_3> points;
      std::vector<std::vector<std::size_t>> polygons;
      diagnose_OFF(filename_, points, polygons);
      file_error(filename_, lines.where() + "face " + std::to_string(j) + " announces " + number + " vertices, " +
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
};

} // namespace mesh_io
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_OFF_FILE_CHECKS_H
