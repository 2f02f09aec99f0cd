// Reading a point cloud from a .vtu file (VTK's XML unstructured grid).
#include "input/particle_vtu.hpp"

#include <fmt/format.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

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

#include "input/vtu_blocks.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

namespace {

// The file, with how it encodes its blocks.
struct Doc : vtu::BlockFormat {
  std::string path;
  std::string bytes;             // the whole file
  std::size_t appended = 0;      // where the appended data starts (after '_'), or npos
  std::size_t appended_end = 0;  // where it ends (the last </AppendedData>)
  std::string appended_encoding;
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

// An ascii DataArray's numbers.
std::vector<double> ascii_values(const Doc& d, const xmlNode* a, const std::string& what) {
  std::vector<double> out;
  std::istringstream in(own_text(a));
  std::string word;
  while (in >> word) {
    double v = 0;
    const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
    if (r.ec != std::errc() || r.ptr != word.data() + word.size())
      fail_at(d, a, fmt::format("{}: value {}: '{}' is not a number", what, out.size(), word));
    out.push_back(v);
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
    out = ascii_values(d, a, what);
  } else if (format == "binary" || format == "appended") {
    std::string text;
    vtu::Source s{nullptr, 0, true};
    if (format == "binary") {
      text = own_text(a);
      s = vtu::Source{&text, 0, true};
    } else {
      if (d.appended == std::string::npos)
        fail_at(d, a, what + ": format=\"appended\" but the file has no AppendedData");
      const std::size_t offset = static_cast<std::size_t>(whole_number(d, a, "offset"));
      if (d.appended_encoding == "raw") {
        s = vtu::Source{&d.bytes, d.appended + offset, false, d.appended_end};
      } else {
        // base64 appended data: the offset counts characters of the encoded text
        s = vtu::Source{&d.bytes, d.appended + offset, true};
      }
    }
    const std::size_t size = static_cast<std::size_t>(sizes.at(type));
    // No array holds more bytes than the file has, times zlib's largest ratio: a count
    // beyond that is not allocated for.
    if (count > (d.bytes.size() + 1) * vtu::kZlibMaxRatio / size)
      fail_at(d, a,
              fmt::format("{}: {} values cannot be held by a file of {} bytes", what, count, d.bytes.size()));
    std::string bytes;
    try {
      bytes = vtu::block_data(d, s, static_cast<std::uint64_t>(count * size));
    } catch (const std::exception& e) {
      fail_at(d, a, fmt::format("{}: cannot decode the {} data: {}", what, format, e.what()));
    }
    out = vtu::values(bytes, type, size, d.swap);
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

// The VTKFile's byte order, header type and compressor, and the appended data's encoding.
void read_encoding(Doc& d, const xmlNode* root) {
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
}

// The arrays' elements, for messages: Points, PointData volume, PointData material (or null).
struct Arrays {
  const xmlNode *x, *volume, *material;
};

// The particles of the arrays read, checked as read_particle_file checks a CSV's rows.
ParticleFile to_particles(const Doc& d, int dim, Arrays a, const std::vector<double>& x3,
                          const std::vector<double>& volume, const std::vector<double>& material) {
  const xmlNode *xa = a.x, *va = a.volume, *ma = a.material;
  const std::string& path = d.path;
  const std::size_t count = volume.size();
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

}  // namespace

ParticleFile read_particle_vtu(const std::string& path, int dim) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the particle file");
  return parse_particle_vtu(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
                            path, dim);
}

ParticleFile parse_particle_vtu(const std::string& contents, const std::string& path, int dim) {
  Doc d;
  d.path = path;
  d.bytes = contents;
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
  read_encoding(d, root);
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

  return to_particles(d, dim, {xa, va, ma}, x3, volume, material);
}

}  // namespace pd
