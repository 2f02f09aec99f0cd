// Reading a point cloud from a .vtu file (VTK's XML unstructured grid).
#include "input/particle_vtu.hpp"

#include <fmt/format.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "input/yaml_keys.hpp"

namespace pd {

namespace {

struct Doc {
  std::string path;
  std::string bytes;             // the whole file
  std::size_t appended = 0;      // where the appended data starts (after '_'), or npos
  std::size_t appended_end = 0;  // where it ends (the last </AppendedData>)
  std::string appended_encoding;
  bool swap = false;     // the file's byte order is not the machine's
  int header_bytes = 4;  // UInt32 or UInt64 block headers
  bool zlib = false;
};

[[noreturn]] void fail_at(const Doc& d, const xmlNode* node, const std::string& message) {
  throw SceneError(fmt::format("{}:{}: {}", d.path, node ? xmlGetLineNo(node) : 1, message));
}

std::string attribute(const xmlNode* node, const char* name) {
  xmlChar* v = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!v) return "";
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}
bool named(const xmlNode* node, const char* name) {
  return node->type == XML_ELEMENT_NODE && std::strcmp(reinterpret_cast<const char*>(node->name), name) == 0;
}
// The element's own text (VTK may nest <InformationKey> elements in a DataArray: not data).
std::string own_text(const xmlNode* node) {
  std::string out;
  for (const xmlNode* c = node->children; c; c = c->next)
    if ((c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) && c->content)
      out += reinterpret_cast<const char*>(c->content), out += ' ';
  return out;
}
std::vector<const xmlNode*> children(const xmlNode* node, const char* name) {
  std::vector<const xmlNode*> out;
  for (const xmlNode* c = node->children; c; c = c->next)
    if (named(c, name)) out.push_back(c);
  return out;
}
long long whole_number(const Doc& d, const xmlNode* node, const char* key) {
  const std::string s = attribute(node, key);
  long long v = -1;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || v < 0)
    fail_at(d, node, fmt::format("{}=\"{}\" is not a non-negative integer", key, s));
  return v;
}

// RFC 4648 base64 (VTK's "binary"), whitespace skipped. Decodes the first `chars`
// characters of `text` from `from`; throws std::runtime_error on a bad character.
std::string base64_decode(const std::string& text, std::size_t from, std::size_t chars) {
  std::string clean;
  for (std::size_t k = from; k < text.size() && clean.size() < chars; ++k)
    if (!std::isspace(static_cast<unsigned char>(text[k]))) clean += text[k];
  if (clean.size() < chars) throw std::runtime_error("the base64 data ends early");
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return -1;
    throw std::runtime_error(fmt::format("'{}' is not a base64 character", c));
  };
  std::string out;
  for (std::size_t k = 0; k + 3 < clean.size(); k += 4) {
    int v[4];
    for (int j = 0; j < 4; ++j) v[j] = value(clean[k + j]);
    if (v[0] < 0 || v[1] < 0) throw std::runtime_error("misplaced base64 padding");
    out += static_cast<char>(v[0] << 2 | v[1] >> 4);
    if (v[2] >= 0) out += static_cast<char>((v[1] & 15) << 4 | v[2] >> 2);
    if (v[2] >= 0 && v[3] >= 0) out += static_cast<char>((v[2] & 3) << 6 | v[3]);
  }
  return out;
}
std::size_t base64_chars(std::size_t bytes) { return 4 * ((bytes + 2) / 3); }

// Where the encoded bytes of one array come from: raw appended bytes, or base64 text.
struct Source {
  const std::string* text;
  std::size_t start;
  bool base64;
  std::size_t end = std::string::npos;  // raw data: where the appended section ends
  // `n` bytes at byte `at` of this block's decoded stream (base64 decodes from the start).
  std::string bytes(std::size_t at, std::size_t n) const {
    if (!base64) {
      if (start + at + n > std::min(end, text->size()))
        throw std::runtime_error("the data ends before the array does");
      return text->substr(start + at, n);
    }
    const std::string all = base64_decode(*text, start, base64_chars(at + n));
    if (all.size() < at + n) throw std::runtime_error("the base64 data ends before the array does");
    return all.substr(at, n);
  }
  // A separately encoded base64 segment starting `chars` characters in (VTK encodes a
  // compressed block's header apart from its data).
  Source after_chars(std::size_t chars) const {
    std::size_t k = start, seen = 0;
    while (k < text->size() && seen < chars)
      seen += std::isspace(static_cast<unsigned char>((*text)[k++])) ? 0 : 1;
    return Source{text, k, true};
  }
};

std::uint64_t header_value(const Doc& d, const std::string& bytes, std::size_t k) {
  std::string b = bytes.substr(k * d.header_bytes, d.header_bytes);
  if (d.swap) std::reverse(b.begin(), b.end());
  if (d.header_bytes == 8) {
    std::uint64_t v;
    std::memcpy(&v, b.data(), 8);
    return v;
  }
  std::uint32_t v;
  std::memcpy(&v, b.data(), 4);
  return v;
}

// The bytes of a binary or appended array, after the block header and decompression.
std::string block_data(const Doc& d, const Source& s) {
  const std::size_t hb = static_cast<std::size_t>(d.header_bytes);
  if (!d.zlib) {
    const std::uint64_t n = header_value(d, s.bytes(0, hb), 0);
    if (n > (1ull << 40)) throw std::runtime_error(fmt::format("a block of {} bytes", n));
    return s.bytes(hb, n);
  }
  // [#blocks][block size][last block size][compressed size of each block], then the
  // zlib streams one after the other (in base64 the header is encoded on its own).
  const std::uint64_t blocks = header_value(d, s.bytes(0, hb), 0);
  if (blocks > (1ull << 30)) throw std::runtime_error(fmt::format("{} compressed blocks", blocks));
  const std::size_t header_size = hb * (3 + blocks);
  const std::string header = s.bytes(0, header_size);
  const std::uint64_t block_size = header_value(d, header, 1), last = header_value(d, header, 2);
  const Source data = s.base64 ? s.after_chars(base64_chars(header_size))
                               : Source{s.text, s.start + header_size, false, s.end};
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) total += header_value(d, header, 3 + b);
  const std::string packed = data.bytes(0, total);
  std::string out;
  std::size_t at = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = header_value(d, header, 3 + b);
    uLongf size = (b + 1 == blocks && last != 0) ? last : block_size;
    std::string chunk(size, '\0');
    if (uncompress(reinterpret_cast<Bytef*>(chunk.data()), &size,
                   reinterpret_cast<const Bytef*>(packed.data() + at), csize) != Z_OK)
      throw std::runtime_error(fmt::format("zlib block {} does not decompress", b));
    chunk.resize(size);
    out += chunk;
    at += csize;
  }
  return out;
}

// One DataArray as doubles (integers converted exactly up to 2^53).
std::vector<double> read_array(const Doc& d, const xmlNode* a, std::size_t count, const std::string& what) {
  const std::string type = attribute(a, "type"), format = attribute(a, "format");
  static const std::map<std::string, int> sizes = {
      {"Float32", 4}, {"Float64", 8}, {"Int8", 1},   {"UInt8", 1}, {"Int16", 2},
      {"UInt16", 2},  {"Int32", 4},   {"UInt32", 4}, {"Int64", 8}, {"UInt64", 8}};
  if (!sizes.count(type)) fail_at(d, a, fmt::format("{}: type=\"{}\" is not a numeric VTK type", what, type));
  std::vector<double> out;
  if (format == "ascii") {
    std::istringstream in(own_text(a));
    std::string word;
    while (in >> word) {
      double v = 0;
      const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
      if (r.ec != std::errc() || r.ptr != word.data() + word.size())
        fail_at(d, a, fmt::format("{}: value {}: '{}' is not a number", what, out.size(), word));
      out.push_back(v);
    }
  } else if (format == "binary" || format == "appended") {
    std::string text;
    Source s{nullptr, 0, true};
    if (format == "binary") {
      text = own_text(a);
      s = Source{&text, 0, true};
    } else {
      if (d.appended == std::string::npos)
        fail_at(d, a, what + ": format=\"appended\" but the file has no AppendedData");
      const std::size_t offset = static_cast<std::size_t>(whole_number(d, a, "offset"));
      if (d.appended_encoding == "raw") {
        s = Source{&d.bytes, d.appended + offset, false, d.appended_end};
      } else {
        // base64 appended data: the offset counts characters of the encoded text
        s = Source{&d.bytes, d.appended + offset, true};
      }
    }
    std::string bytes;
    try {
      bytes = block_data(d, s);
    } catch (const std::exception& e) {
      fail_at(d, a, fmt::format("{}: cannot decode the {} data: {}", what, format, e.what()));
    }
    const std::size_t size = static_cast<std::size_t>(sizes.at(type));
    if (bytes.size() % size != 0)
      fail_at(d, a, fmt::format("{}: {} bytes is not a whole number of {}", what, bytes.size(), type));
    out.resize(bytes.size() / size);
    for (std::size_t k = 0; k < out.size(); ++k) {
      char b[8];
      std::memcpy(b, bytes.data() + k * size, size);
      if (d.swap) std::reverse(b, b + size);
      auto get = [&]<class T>(T) {
        T v;
        std::memcpy(&v, b, sizeof v);
        return static_cast<double>(v);
      };
      if (type == "Float32")
        out[k] = get(float{});
      else if (type == "Float64")
        out[k] = get(double{});
      else if (type == "Int8")
        out[k] = get(std::int8_t{});
      else if (type == "UInt8")
        out[k] = get(std::uint8_t{});
      else if (type == "Int16")
        out[k] = get(std::int16_t{});
      else if (type == "UInt16")
        out[k] = get(std::uint16_t{});
      else if (type == "Int32")
        out[k] = get(std::int32_t{});
      else if (type == "UInt32")
        out[k] = get(std::uint32_t{});
      else if (type == "Int64")
        out[k] = get(std::int64_t{});
      else
        out[k] = get(std::uint64_t{});
    }
  } else {
    fail_at(d, a, fmt::format("{}: format=\"{}\" (VTK writes ascii, binary or appended)", what, format));
  }
  if (out.size() != count)
    fail_at(d, a, fmt::format("{}: {} values where {} were expected", what, out.size(), count));
  return out;
}

// The one DataArray of `parent` named `name` (or the only one, for Points), or null.
const xmlNode* find_array(const Doc& d, const xmlNode* parent, const char* name) {
  const xmlNode* found = nullptr;
  if (!parent) return nullptr;
  for (const xmlNode* a : children(parent, "DataArray")) {
    if (name && attribute(a, "Name") != name) continue;
    if (found)
      fail_at(d, a,
              fmt::format("a second DataArray '{}' (the first is on line {})", name ? name : "",
                          xmlGetLineNo(found)));
    found = a;
  }
  return found;
}

}  // namespace

ParticleFile read_particle_vtu(const std::string& path, int dim) {
  Doc d;
  d.path = path;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open the particle file");
    d.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // Raw appended data is not XML: parse only what comes before it (lines keep their numbers).
  std::string xml = d.bytes;
  d.appended = std::string::npos;
  const std::size_t tag = d.bytes.find("<AppendedData");
  if (tag != std::string::npos) {
    const std::size_t close = d.bytes.find('>', tag);
    const std::size_t mark = close == std::string::npos ? close : d.bytes.find('_', close);
    if (mark == std::string::npos) throw SceneError(path + ": AppendedData without its '_' marker");
    d.appended = mark + 1;
    d.appended_end = d.bytes.rfind("</AppendedData>");
    if (d.appended_end == std::string::npos || d.appended_end < d.appended) d.appended_end = d.bytes.size();
    xml = d.bytes.substr(0, close + 1) + "</AppendedData></VTKFile>";
  }
  std::unique_ptr<xmlDoc, void (*)(xmlDoc*)> doc(
      xmlReadMemory(xml.data(), static_cast<int>(xml.size()), path.c_str(), nullptr,
                    XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
      xmlFreeDoc);
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    std::string message = e && e->message ? e->message : "not XML";
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw SceneError(fmt::format("{}:{}: not a VTK XML file: {}", path, e ? e->line : 1, message));
  }
  const xmlNode* root = xmlDocGetRootElement(doc.get());
  if (!root || !named(root, "VTKFile") || attribute(root, "type") != "UnstructuredGrid")
    fail_at(d, root, "not a VTK unstructured grid (<VTKFile type=\"UnstructuredGrid\">)");
  const std::string order = attribute(root, "byte_order"), header = attribute(root, "header_type"),
                    compressor = attribute(root, "compressor");
  if (order != "LittleEndian" && order != "BigEndian" && !order.empty())
    fail_at(d, root, fmt::format("byte_order=\"{}\" (LittleEndian or BigEndian)", order));
  d.swap = (order == "BigEndian") != (std::endian::native == std::endian::big) && !order.empty();
  if (header == "UInt64")
    d.header_bytes = 8;
  else if (!header.empty() && header != "UInt32")
    fail_at(d, root, fmt::format("header_type=\"{}\" (UInt32 or UInt64)", header));
  if (compressor == "vtkZLibDataCompressor")
    d.zlib = true;
  else if (!compressor.empty())
    fail_at(d, root,
            fmt::format("compressor=\"{}\": only vtkZLibDataCompressor (or none) is read; write with "
                        "SetCompressorTypeToZLib() or SetCompressorTypeToNone()",
                        compressor));
  for (const xmlNode* a : children(root, "AppendedData")) {
    d.appended_encoding = attribute(a, "encoding");
    if (d.appended_encoding != "raw" && d.appended_encoding != "base64")
      fail_at(d, a, fmt::format("AppendedData encoding=\"{}\" (raw or base64)", d.appended_encoding));
  }
  const std::vector<const xmlNode*> grids = children(root, "UnstructuredGrid");
  if (grids.size() != 1) fail_at(d, root, "no UnstructuredGrid element");
  const std::vector<const xmlNode*> pieces = children(grids[0], "Piece");
  if (pieces.size() != 1)
    fail_at(d, grids[0],
            fmt::format("{} Piece elements: one is read (merge the pieces first)", pieces.size()));
  const xmlNode* piece = pieces[0];
  const long long n = whole_number(d, piece, "NumberOfPoints");
  if (n == 0) fail_at(d, piece, "the grid has no points");

  const std::vector<const xmlNode*> points = children(piece, "Points"),
                                    point_data = children(piece, "PointData");
  if (points.size() != 1) fail_at(d, piece, "no Points element");
  const xmlNode* xa = find_array(d, points[0], nullptr);
  if (!xa) fail_at(d, points[0], "Points without a DataArray");
  if (attribute(xa, "NumberOfComponents") != "3") fail_at(d, xa, "Points: NumberOfComponents must be 3");
  const xmlNode* va = point_data.empty() ? nullptr : find_array(d, point_data[0], "volume");
  if (!va)
    fail_at(d, point_data.empty() ? piece : point_data[0],
            "no point data array 'volume' (each particle's volume, an area in 2D)");
  const xmlNode* ma = point_data.empty() ? nullptr : find_array(d, point_data[0], "material");
  for (const xmlNode* a : {va, ma}) {
    const std::string nc = a ? attribute(a, "NumberOfComponents") : "";
    if (!nc.empty() && nc != "1")
      fail_at(d, a, fmt::format("PointData '{}': NumberOfComponents must be 1", attribute(a, "Name")));
  }
  const std::size_t count = static_cast<std::size_t>(n);
  const std::vector<double> x3 = read_array(d, xa, 3 * count, "Points");
  const std::vector<double> volume = read_array(d, va, count, "PointData 'volume'");
  const std::vector<double> material =
      ma ? read_array(d, ma, count, "PointData 'material'") : std::vector<double>();

  ParticleFile f;
  f.path = path;
  f.dim = dim;
  f.point_ids = true;
  std::set<std::vector<double>> seen;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<double> x(x3.begin() + static_cast<std::ptrdiff_t>(3 * i),
                          x3.begin() + static_cast<std::ptrdiff_t>(3 * i + dim));
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(x3[3 * i + c]))
        fail_at(d, xa, fmt::format("Points: point id {}: coordinate {} is not finite", i, c));
    if (dim == 2 && x3[3 * i + 2] != 0)
      fail_at(
          d, xa,
          fmt::format("Points: point id {}: z = {} in a 2D scene (2D points have z = 0)", i, x3[3 * i + 2]));
    if (!(volume[i] > 0) || !std::isfinite(volume[i]))
      fail_at(d, va,
              fmt::format("PointData 'volume': point id {}: volume must be positive and finite (got {})", i,
                          volume[i]));
    if (!seen.insert(x).second)
      fail_at(d, xa, fmt::format("Points: point id {}: a second particle at the same position", i));
    std::string m;
    if (ma) {
      const double v = material[i];
      if (!(v >= 0) || v != std::floor(v) || v > 1e9)
        fail_at(
            d, ma,
            fmt::format("PointData 'material': point id {}: {} is not a material index (0, 1, ...)", i, v));
      m = std::to_string(static_cast<long long>(v));
    }
    f.x.insert(f.x.end(), x.begin(), x.end());
    f.volume.push_back(volume[i]);
    f.material.push_back(m);
    f.line.push_back(static_cast<int>(xmlGetLineNo(ma ? ma : va)));
  }
  return f;
}

}  // namespace pd
