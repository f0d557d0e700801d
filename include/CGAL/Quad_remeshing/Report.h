// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small ordered, JSON-like record that every stage fills with its figures.

#ifndef CGAL_QUAD_REMESHING_REPORT_H
#define CGAL_QUAD_REMESHING_REPORT_H

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  A value of a stage report: null, Boolean, number, string, array or object (keys keep their
  insertion order). Every stage returns its figures (counts, seconds, status) in such a record so that
  the command-line program can write them as JSON without knowing each stage.
*/
class Report
{
public:
  enum Kind { NULL_VALUE, BOOLEAN, NUMBER, STRING, ARRAY, OBJECT };

  Report() = default;
  Report(bool b) : kind_(BOOLEAN), number_(b ? 1. : 0.) {}
  Report(double d) : kind_(NUMBER), number_(d) {}
  Report(int i) : kind_(NUMBER), number_(double(i)) {}
  Report(long i) : kind_(NUMBER), number_(double(i)) {}
  Report(long long i) : kind_(NUMBER), number_(double(i)) {}
  Report(unsigned i) : kind_(NUMBER), number_(double(i)) {}
  Report(unsigned long i) : kind_(NUMBER), number_(double(i)) {}
  Report(unsigned long long i) : kind_(NUMBER), number_(double(i)) {}
  Report(const char* s) : kind_(STRING), string_(s) {}
  Report(std::string s) : kind_(STRING), string_(std::move(s)) {}

  /// an empty object
  static Report object() { Report r; r.kind_ = OBJECT; return r; }
  /// an empty array
  static Report array() { Report r; r.kind_ = ARRAY; return r; }

  Kind kind() const { return kind_; }
  bool is_null() const { return kind_ == NULL_VALUE; }
  double number() const { return number_; }
  bool boolean() const { return number_ != 0.; }
  const std::string& string() const { return string_; }

  /// Object access: returns the value of `key`, inserting a null value at the end if it is absent.
  /// A null value becomes an object on first access.
  Report& operator[](const std::string& key)
  {
    if(kind_ == NULL_VALUE) kind_ = OBJECT;
    if(kind_ != OBJECT) throw std::logic_error("Report: not an object");
    for(std::size_t i = 0; i < keys_.size(); ++i)
      if(keys_[i] == key) return elements_[i];
    keys_.push_back(key);
    elements_.emplace_back();
    return elements_.back();
  }

  /// Returns a pointer to the value of `key`, or `nullptr`.
  const Report* find(const std::string& key) const
  {
    for(std::size_t i = 0; i < keys_.size(); ++i)
      if(keys_[i] == key) return &elements_[i];
    return nullptr;
  }

  /// Appends to an array (a null value becomes an array).
  Report& push_back(Report v)
  {
    if(kind_ == NULL_VALUE) kind_ = ARRAY;
    if(kind_ != ARRAY) throw std::logic_error("Report: not an array");
    elements_.push_back(std::move(v));
    return elements_.back();
  }

  /// number of elements of an array or members of an object
  std::size_t size() const { return elements_.size(); }
  /// the elements of an array, or the values of an object in insertion order
  const std::vector<Report>& elements() const { return elements_; }
  /// the keys of an object in insertion order
  const std::vector<std::string>& keys() const { return keys_; }

  /// Writes the value as JSON; `indent < 0` writes one line.
  void write_json(std::ostream& os, int indent = 2) const { write(os, indent, 0); }

  std::string to_json(int indent = 2) const
  {
    std::ostringstream os;
    write_json(os, indent);
    return os.str();
  }

  /// Parses JSON text (as written by `write_json()`; numbers, strings with the usual escapes,
  /// `true`/`false`/`null`, arrays and objects). Throws `std::runtime_error` on malformed text.
  static Report parse(const std::string& text)
  {
    std::size_t pos = 0;
    Report r = parse_value(text, pos);
    skip_space(text, pos);
    if(pos != text.size()) throw std::runtime_error("Report::parse: trailing characters");
    return r;
  }

private:
  static void skip_space(const std::string& t, std::size_t& pos)
  {
    while(pos < t.size() && (t[pos] == ' ' || t[pos] == '\n' || t[pos] == '\t' || t[pos] == '\r')) ++pos;
  }

  static void expect(const std::string& t, std::size_t& pos, char c)
  {
    skip_space(t, pos);
    if(pos >= t.size() || t[pos] != c) throw std::runtime_error(std::string("Report::parse: expected '") + c + "'");
    ++pos;
  }

  static std::string parse_string(const std::string& t, std::size_t& pos)
  {
    expect(t, pos, '"');
    std::string out;
    while(pos < t.size() && t[pos] != '"')
    {
      char c = t[pos++];
      if(c == '\\')
      {
        if(pos >= t.size()) break;
        const char e = t[pos++];
        switch(e)
        {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'u':
          {
            if(pos + 4 > t.size()) throw std::runtime_error("Report::parse: bad \\u escape");
            const unsigned code = unsigned(std::stoul(t.substr(pos, 4), nullptr, 16));
            pos += 4;
            out += code < 0x80 ? char(code) : '?'; // the package only writes ASCII control escapes
            break;
          }
          default: out += e;
        }
      }
      else out += c;
    }
    if(pos >= t.size()) throw std::runtime_error("Report::parse: unterminated string");
    ++pos;
    return out;
  }

  static Report parse_value(const std::string& t, std::size_t& pos)
  {
    skip_space(t, pos);
    if(pos >= t.size()) throw std::runtime_error("Report::parse: unexpected end");
    const char c = t[pos];
    if(c == '{')
    {
      ++pos;
      Report r = object();
      skip_space(t, pos);
      if(pos < t.size() && t[pos] == '}') { ++pos; return r; }
      for(;;)
      {
        const std::string key = parse_string(t, pos);
        expect(t, pos, ':');
        r[key] = parse_value(t, pos);
        skip_space(t, pos);
        if(pos < t.size() && t[pos] == ',') { ++pos; continue; }
        expect(t, pos, '}');
        return r;
      }
    }
    if(c == '[')
    {
      ++pos;
      Report r = array();
      skip_space(t, pos);
      if(pos < t.size() && t[pos] == ']') { ++pos; return r; }
      for(;;)
      {
        r.push_back(parse_value(t, pos));
        skip_space(t, pos);
        if(pos < t.size() && t[pos] == ',') { ++pos; continue; }
        expect(t, pos, ']');
        return r;
      }
    }
    if(c == '"') return Report(parse_string(t, pos));
    if(t.compare(pos, 4, "true") == 0) { pos += 4; return Report(true); }
    if(t.compare(pos, 5, "false") == 0) { pos += 5; return Report(false); }
    if(t.compare(pos, 4, "null") == 0) { pos += 4; return Report(); }
    const char* begin = t.c_str() + pos;
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if(end == begin) throw std::runtime_error("Report::parse: unexpected character");
    pos += std::size_t(end - begin);
    return Report(v);
  }

  static void write_string(std::ostream& os, const std::string& s)
  {
    os << '"';
    for(unsigned char c : s)
    {
      switch(c)
      {
        case '"': os << "\\\""; break;
        case '\\': os << "\\\\"; break;
        case '\n': os << "\\n"; break;
        case '\t': os << "\\t"; break;
        case '\r': os << "\\r"; break;
        default:
          if(c < 0x20) os << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec << std::setfill(' ');
          else os << c;
      }
    }
    os << '"';
  }

  void newline(std::ostream& os, int indent, int depth) const
  {
    if(indent < 0) return;
    os << '\n' << std::string(std::size_t(indent * depth), ' ');
  }

  void write(std::ostream& os, int indent, int depth) const
  {
    switch(kind_)
    {
      case NULL_VALUE: os << "null"; break;
      case BOOLEAN: os << (number_ != 0. ? "true" : "false"); break;
      case NUMBER:
        if(!std::isfinite(number_)) os << "null"; // JSON has no inf/nan
        else if(number_ == std::floor(number_) && std::abs(number_) < 1e15) os << static_cast<long long>(number_);
        else os << std::setprecision(10) << number_;
        break;
      case STRING: write_string(os, string_); break;
      case ARRAY:
        os << '[';
        for(std::size_t i = 0; i < elements_.size(); ++i)
        {
          if(i) os << ',';
          newline(os, indent, depth + 1);
          elements_[i].write(os, indent, depth + 1);
        }
        if(!elements_.empty()) newline(os, indent, depth);
        os << ']';
        break;
      case OBJECT:
        os << '{';
        for(std::size_t i = 0; i < keys_.size(); ++i)
        {
          if(i) os << ',';
          newline(os, indent, depth + 1);
          write_string(os, keys_[i]);
          os << (indent < 0 ? ":" : ": ");
          elements_[i].write(os, indent, depth + 1);
        }
        if(!keys_.empty()) newline(os, indent, depth);
        os << '}';
        break;
    }
  }

  Kind kind_ = NULL_VALUE;
  double number_ = 0.;
  std::string string_;
  std::vector<std::string> keys_;     // objects only
  std::vector<Report> elements_;      // array elements, or object values (parallel to keys_)
};

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_REPORT_H
