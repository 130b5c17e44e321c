// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks of a PLY file before CGAL's PLY reader reads it: the element
// counts its header announces and the sizes of its lists must fit in the file.
#ifndef GEODESIC_RIDGE_INTERNAL_PLY_FILE_CHECKS_H
#define GEODESIC_RIDGE_INTERNAL_PLY_FILE_CHECKS_H

#include <Geodesic_ridge/internal/mesh_file_text.h>
#include <Geodesic_ridge/internal/ply_face_layouts.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace mesh_io {

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

// The counts of a PLY file's elements and lists, as CGAL's PLY reader reads
// them, must fit in the file (the reason: OFF_file_checks).
class PLY_file_checks : public File_size_checks
{
public:
  explicit PLY_file_checks(const std::string& filename) : File_size_checks(filename) {}

  void check_counts() const
  {
    if(size_ != 0) check_PLY();
  }

private:
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

  // The header as CGAL's reader takes it (at most 100000 lines).
  struct Ply_header
  {
    bool ply = false;      // the first line says "ply"
    bool readable = true;  // CGAL's reader reads it (else it fails, and says so)
    bool ended = false;    // an "end_header" line
    bool gave_up = false;  // an element line CGAL's reader fails on (and says what is wrong)
    bool binary = false;
    int format = -1;       // 0 ASCII, 1 little-endian, 2 big-endian, -1 none CGAL's reader knows
    std::vector<Ply_element> elements;
    std::uintmax_t bytes = 0; // of the lines read
    int lines = 0;
  };

  void check_PLY() const
  {
    std::ifstream in(filename_, std::ios::binary);
    const Ply_header h = read_PLY_header(in);
    if(h.gave_up) return;
    if(!h.ended)
    {
      // CGAL's reader takes the whole file as the header, then reads the
      // items from the failed stream: a list sized from uninitialized memory
      if(h.ply && h.lines < 100000)
        file_error(filename_, "malformed or truncated PLY header: no 'end_header' line");
      return;
    }
    const std::uintmax_t body = (std::min)(size_, h.bytes);
    check_PLY_sizes(h, body);
    if(h.ply && h.readable && h.format >= 0)
      check_PLY_lists(h.elements, h.format, body);
  }

  Ply_header read_PLY_header(std::istream& in) const
  {
    Ply_header h;
    std::string line;
    for(; h.lines < 100000 && std::getline(in, line); ++h.lines)
    {
      h.bytes += line.size() + 1;
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if(h.lines == 0)
        h.ply = keyword == "ply";
      else if(h.lines == 1)
      {
        // CGAL's reader takes the format from the second line, whatever its
        // first word (an "element" there is none; found by fuzz/)
        std::string f, version;
        h.readable = static_cast<bool>(words >> f >> version);
        h.format = f == "ascii" ? 0 : f == "binary_little_endian" ? 1 : f == "binary_big_endian" ? 2 : -1;
        h.binary = f != "ascii";
      }
      else if(keyword.empty())
        h.readable = false; // (CGAL's reader fails on an empty header line)
      else if(keyword == "element")
      {
        Ply_element e;
        if(!(words >> e.name >> e.count)) { h.gave_up = true; return h; }
        h.elements.push_back(e);
      }
      else if(keyword == "property")
        add_PLY_property(words, h);
      else if(keyword == "end_header")
      {
        h.ended = true;
        break;
      }
    }
    return h;
  }

  // a "property" line (after its keyword) of header line h.lines
  void add_PLY_property(std::istringstream& words, Ply_header& h) const
  {
    auto at = [&] { return " (line " + std::to_string(h.lines + 1) + ")"; }; // (only for an error)
    if(h.elements.empty())
      // CGAL's reader adds a property to its last element, and has none
      // yet: it would read out of bounds (found by fuzz/)
      file_error(filename_, "PLY header: a property before any element" + at());
    Ply_element& element = h.elements.back();
    const bool of_vertex = ply::is_vertex_element(element.name);
    std::string type, name;
    words >> type >> name;
    Ply_property p;
    if(type == "list") // "list COUNT ITEM NAME"; CGAL's reader takes integer counts only
    {
      std::string item;
      words >> item >> p.name;
      if(of_vertex && (p.name == "x" || p.name == "y" || p.name == "z"))
        // (as below: CGAL's point reader asserts on it; found by fuzz/)
        file_error(filename_, "PLY header: vertex coordinate '" + p.name + "' is a list, not float or double" + at());
      p.list = true;
      p.count = ply_type(name);
      p.type = ply_type(item);
      if(p.count.is_float) p.count.bytes = 0;
    }
    else
    {
      if(of_vertex && (name == "x" || name == "y" || name == "z") && type != "float" && type != "float32" &&
         type != "double" && type != "float64")
        // CGAL's point reader asserts (and without assertions dereferences
        // null) on an integer coordinate (found by fuzz/)
        file_error(filename_, "PLY header: vertex coordinate '" + name + "' is '" + type + "', not float or double" + at());
      p.name = name;
      p.type = ply_type(type);
    }
    if(p.name.empty())
      h.readable = false; // (CGAL's reader fails on it)
    else if(p.type.bytes != 0 && (!p.list || p.count.bytes != 0))
    {
      element.least += h.binary ? (p.list ? p.count.bytes : p.type.bytes) : 2;
      element.properties.push_back(p);
    }
  }

  // The items the header announces fit in the file's `body` bytes after it,
  // or the file is refused before CGAL's reader allocates for them.
  void check_PLY_sizes(const Ply_header& h, std::uintmax_t body) const
  {
    long double least = 0;
    std::string announced;
    bool absurd = false;
    for(const Ply_element& e : h.elements)
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
    if(least > static_cast<long double>(size_ - body) + (h.binary ? 0 : 1))
      refuse(announced, static_cast<std::uintmax_t>((std::min)(least + h.bytes, 1.8e19L)));
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
};

} // namespace mesh_io
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_PLY_FILE_CHECKS_H
