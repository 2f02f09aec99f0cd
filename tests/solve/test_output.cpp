// VTU and CSV writers: a well-formed binary VTU with the right counts and exact values, CSV shape, atomic
// writes.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "support_grid.hpp"
#include "temp_files.hpp"

namespace {
struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<Element> children;
};

// A strict little XML reader for what the writer emits (declaration, elements,
// quoted attributes, text): throws on anything malformed, e.g. a mismatched tag.
class Xml {
 public:
  explicit Xml(std::string s) : s_(std::move(s)) {}
  Element parse() {
    skip_ws();
    if (s_.compare(i_, 5, "<?xml") == 0) i_ = s_.find("?>", i_) + 2;
    skip_ws();
    Element root = element();
    skip_ws();
    if (i_ != s_.size()) throw std::runtime_error("content after the root element");
    return root;
  }

 private:
  void skip_ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string name() {
    const std::size_t b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
    if (b == i_) throw std::runtime_error("expected a name at " + std::to_string(b));
    return s_.substr(b, i_ - b);
  }
  Element element() {
    if (s_[i_] != '<') throw std::runtime_error("expected '<' at " + std::to_string(i_));
    ++i_;
    Element e;
    e.name = name();
    for (;;) {
      skip_ws();
      if (s_.compare(i_, 2, "/>") == 0) {
        i_ += 2;
        return e;
      }
      if (s_[i_] == '>') break;
      const std::string key = name();
      if (s_[i_++] != '=' || s_[i_++] != '"') throw std::runtime_error("bad attribute " + key);
      const std::size_t end = s_.find('"', i_);
      if (e.attributes.count(key)) throw std::runtime_error("repeated attribute " + key);
      e.attributes[key] = s_.substr(i_, end - i_);
      i_ = end + 1;
    }
    ++i_;
    for (;;) {
      const std::size_t lt = s_.find('<', i_);
      if (lt == std::string::npos) throw std::runtime_error("unclosed <" + e.name + ">");
      e.text += s_.substr(i_, lt - i_);
      i_ = lt;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (name() != e.name || s_[i_++] != '>') throw std::runtime_error("mismatched </" + e.name + ">");
        return e;
      }
      e.children.push_back(element());
    }
  }
  std::string s_;
  std::size_t i_ = 0;
};

const Element& child(const Element& e, const std::string& name) {
  for (const auto& c : e.children)
    if (c.name == name) return c;
  throw std::runtime_error("no <" + name + "> in <" + e.name + ">");
}
std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The head of a binary VTU (XML up to the appended section) and the raw bytes after '_'.
struct BinaryVtu {
  Element root;
  std::string data;
};
BinaryVtu split_binary_vtu(const std::string& doc) {
  const std::string open = "<AppendedData encoding=\"raw\">";
  const std::size_t at = doc.find(open);
  if (at == std::string::npos) throw std::runtime_error("no raw <AppendedData>");
  const std::size_t underscore = doc.find('_', at + open.size());
  const std::size_t close = doc.rfind("\n  </AppendedData>");
  if (underscore == std::string::npos || close == std::string::npos || close < underscore)
    throw std::runtime_error("bad appended section");
  return {Xml(doc.substr(0, at) + "</VTKFile>").parse(), doc.substr(underscore + 1, close - underscore - 1)};
}
// One appended block: a UInt64 byte count, then the values.
template <class T>
std::vector<T> block(const BinaryVtu& v, const Element& array) {
  const std::size_t offset = std::stoull(array.attributes.at("offset"));
  std::uint64_t bytes = 0;
  if (offset + sizeof bytes > v.data.size()) throw std::runtime_error("offset past the data");
  std::memcpy(&bytes, v.data.data() + offset, sizeof bytes);
  if (offset + sizeof bytes + bytes > v.data.size() || bytes % sizeof(T) != 0)
    throw std::runtime_error("bad block size");
  std::vector<T> out(bytes / sizeof(T));
  if (bytes > 0) std::memcpy(out.data(), v.data.data() + offset + sizeof bytes, bytes);
  return out;
}
}  // namespace

TEST(Output, VtuIsBinaryWithTheRightCountsAndExactValues) {
  const auto body = pd::test::make_grid(2, 5, 4, 1, 1.5, 0.1);
  const int n = body.particles.size();
  std::vector<double> u(2 * n);
  for (int i = 0; i < 2 * n; ++i) u[i] = 1e-3 * i + 1.0 / 3.0;
  std::vector<pd::OutputField> fields{{"damage", 1, std::vector<double>(n, 0.25)},
                                      {"force", 2, std::vector<double>(2 * n, -1.5)}};
  const auto dir = pd::test::scratch_path("pd_solve_test_output");
  const auto path = dir / "sub" / "result.vtu";
  pd::write_vtu_file(path.string(), body.particles, u, fields);
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path.parent_path()), {}), 1)
      << "a temporary was left";
  const std::string doc = read(path);
  const BinaryVtu v = split_binary_vtu(doc);
  EXPECT_EQ(v.root.name, "VTKFile");
  EXPECT_EQ(v.root.attributes.at("type"), "UnstructuredGrid");
  EXPECT_EQ(v.root.attributes.at("header_type"), "UInt64");
  EXPECT_EQ(v.root.attributes.at("byte_order"),
            std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian");
  const Element& piece = child(child(v.root, "UnstructuredGrid"), "Piece");
  EXPECT_EQ(piece.attributes.at("NumberOfPoints"), std::to_string(n));
  EXPECT_EQ(piece.attributes.at("NumberOfCells"), std::to_string(n));
  const auto points = block<double>(v, child(child(piece, "Points"), "DataArray"));
  ASSERT_EQ(points.size(), 3u * n);
  EXPECT_EQ(points[3 * 7 + 1], body.particles.x[2 * 7 + 1]);
  const Element& cells = child(piece, "Cells");
  ASSERT_EQ(cells.children.size(), 3u);
  for (const auto& a : cells.children) {
    EXPECT_EQ(a.attributes.at("format"), "appended");
    const std::string& name = a.attributes.at("Name");
    if (name == "types") {
      const auto t = block<std::uint8_t>(v, a);
      ASSERT_EQ(t.size(), static_cast<std::size_t>(n));
      for (auto x : t) EXPECT_EQ(x, 1);  // VTK_VERTEX
    } else {
      const auto c = block<std::int64_t>(v, a);
      ASSERT_EQ(c.size(), static_cast<std::size_t>(n)) << name;
      EXPECT_EQ(c.back(), name == "offsets" ? n : n - 1);
    }
  }
  const Element& pd_data = child(piece, "PointData");
  ASSERT_EQ(pd_data.children.size(), 3u);
  std::map<std::string, std::vector<double>> arrays;
  for (const auto& a : pd_data.children) arrays[a.attributes.at("Name")] = block<double>(v, a);
  ASSERT_EQ(arrays["displacement"].size(), 3u * n);
  EXPECT_EQ(arrays["displacement"][3 * 4 + 1], u[2 * 4 + 1]);  // exact round trip, z padded
  EXPECT_EQ(arrays["displacement"][3 * 4 + 2], 0.0);
  EXPECT_EQ(arrays["damage"].size(), static_cast<std::size_t>(n));
  EXPECT_EQ(arrays["force"].size(), 3u * n);
  // Binary: 8 bytes a Float64 (ASCII with 17 digits took about 24).
  EXPECT_LT(doc.size(), 8u * (3 + 3 + 1 + 3) * n + 17u * n + 2000);
  std::filesystem::remove_all(dir);
}

TEST(Output, XmlCheckerRejectsMalformedDocuments) {
  EXPECT_THROW(Xml("<a><b></a></b>").parse(), std::runtime_error);
  EXPECT_THROW(Xml("<a x=\"1\"><b/>").parse(), std::runtime_error);
  EXPECT_NO_THROW(Xml("<?xml version=\"1.0\"?>\n<a x=\"1\"><b/>text</a>").parse());
}

TEST(Output, TemporariesAreUniquePerWrite) {
  // Two writers of one path (two runs, or two threads) must not share a temporary: each
  // write's temporary is new, so interleaved writes publish one whole file or the other.
  const auto dir = pd::test::scratch_path("pd_solve_test_tmp_names");
  const std::string path = (dir / "f.txt").string();
  std::vector<std::thread> writers;
  for (int t = 0; t < 4; ++t)
    writers.emplace_back([&, t] {
      for (int k = 0; k < 50; ++k)
        pd::write_file_atomically(path, std::string(10000, static_cast<char>('a' + t)));
    });
  for (auto& w : writers) w.join();
  const std::string text = read(path);
  ASSERT_EQ(text.size(), 10000u);
  EXPECT_EQ(text, std::string(10000, text[0]));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1) << "a temporary was left";
  std::filesystem::remove_all(dir);
}

TEST(Output, CsvHasHeaderAndOneRowPerParticle) {
  const auto body = pd::test::make_grid(3, 3, 2, 2, 1.5);
  const int n = body.particles.size();
  std::vector<double> u(3 * n, 0.5);
  std::vector<pd::OutputField> fields{{"theta", 1, std::vector<double>(n, 2.0)},
                                      {"f", 3, std::vector<double>(3 * n, 1.0)}};
  const std::string csv = pd::csv_document(body.particles, u, fields);
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "id,x,y,z,u_x,u_y,u_z,theta,f_x,f_y,f_z");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 10);
  }
  EXPECT_EQ(rows, n);
}

TEST(Output, BadFieldsAndUnwritablePathsFailWithoutAFile) {
  const auto body = pd::test::make_grid(2, 3, 3, 1, 1.5);
  std::vector<pd::OutputField> bad{{"short", 1, std::vector<double>(2, 0.0)}};
  const auto dir = pd::test::scratch_path("pd_solve_test_bad");
  const auto path = dir / "r.vtu";
  EXPECT_THROW(pd::write_vtu_file(path.string(), body.particles, {}, bad), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
  // A directory where the file should go: the rename fails and no temporary is left.
  std::filesystem::create_directories(path);
  EXPECT_THROW(pd::write_file_atomically(path.string(), "x"), std::runtime_error);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1) << "a temporary was left";
  std::filesystem::remove_all(dir);
}
