// Issue 18 "your own fuzzers", the mesh half in its short, seeded form: mutations of the
// bundled meshes in every format read_tet_mesh takes (gmsh 2.2/4.1 ASCII and binary, VTK XML
// raw/base64/zlib/ascii, Medit, TetGen) must either load or be refused with an InputError
// naming the file; nothing else may escape, no input may take long, and a mesh that loads
// holds what mesh_check.hpp promises: finite coordinates, indices in range and distinct,
// every tet positively oriented with quality >= kMinTetQuality, no unused vertex.
// Mutations: bit flips, truncation, deleted/duplicated/swapped lines, copied or cut byte
// ranges, numbers replaced by hostile ones (1e308, nan, inf, huge or negative counts and
// indices) or nudged by one, header counts and attributes that lie, binary fields overwritten
// with extreme values, stray bytes (NUL, 0xff, BOM) and wrong encodings (CRLF, UTF-16, NULs).
// scripts/fuzz_meshes.sh runs it longer (MRSIM_FUZZ_INPUTS) with other seeds
// (MRSIM_FUZZ_SEED); inputs that fail are kept in $TMPDIR/mrsim_mesh_fuzz_failures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "mesh/mesh_check.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

using namespace std::string_view_literals;

struct Seed {
  std::string name;     // file name, read under this name (the extension picks the reader)
  std::string bytes;    // original content
  std::string partner;  // TetGen: the other file of the pair, copied intact ("" if none)
  std::string partner_bytes;
};

bool is_mesh_extension(const std::string& ext) {
  return ext == ".msh" || ext == ".vtu" || ext == ".mesh" || ext == ".node" || ext == ".ele";
}

// Every fixture of tests/data/mesh (all formats and variants) and the small bundled meshes
// of scenarios/meshes (what `mrsim run` reads: zlib-compressed UInt64 .vtu, MSH 2.2).
std::vector<Seed> seeds() {
  std::vector<Seed> out;
  auto add = [&](const fs::path& path) {
    const std::string ext = path.extension().string();
    if (!is_mesh_extension(ext)) return;
    Seed s{path.filename().string(), read_file(path), "", ""};
    if (ext == ".node" || ext == ".ele") {
      fs::path other = path;
      other.replace_extension(ext == ".node" ? ".ele" : ".node");
      s.partner = other.filename().string();
      s.partner_bytes = read_file(other);
    }
    out.push_back(std::move(s));
  };
  for (const auto& e : fs::directory_iterator(fixture_dir())) add(e.path());
  for (const auto& e : fs::directory_iterator(source_dir() / "scenarios" / "meshes"))
    if (e.file_size() < 16 * 1024) add(e.path());
  // Directory order is unspecified: sort, so that a seed gives the same inputs everywhere.
  std::sort(out.begin(), out.end(), [](const Seed& a, const Seed& b) { return a.name < b.name; });
  return out;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E';
}

// [begin, end) of the number-like run around the first digit at or after `from` (wrapping);
// {npos, npos} if the text holds no digit.
std::pair<std::size_t, std::size_t> number_at(const std::string& text, std::size_t from) {
  std::size_t at = std::string::npos;
  for (std::size_t i = 0; i < text.size() && at == std::string::npos; ++i) {
    const std::size_t j = (from + i) % text.size();
    if (text[j] >= '0' && text[j] <= '9') at = j;
  }
  if (at == std::string::npos) return {at, at};
  std::size_t begin = at, end = at;
  while (begin > 0 && is_number_char(text[begin - 1])) --begin;
  while (end < text.size() && is_number_char(text[end])) ++end;
  return {begin, end};
}

// "1\0002"sv is '1', NUL, '2'; "\xd9\xa3" is an Arabic-Indic three.
const std::string_view kHostileNumbers[] = {"1e308",
                                            "-1e308",
                                            "1e309",
                                            "-1e999",
                                            "1.7976931348623157e308",
                                            "nan",
                                            "-nan",
                                            "NaN",
                                            "inf",
                                            "-inf",
                                            "Infinity",
                                            "1e-320",
                                            "4.9e-324",
                                            "0",
                                            "-0",
                                            "-1",
                                            "-2147483648",
                                            "2147483647",
                                            "2147483648",
                                            "4294967295",
                                            "4294967296",
                                            "9223372036854775807",
                                            "9223372036854775808",
                                            "-9223372036854775809",
                                            "18446744073709551615",
                                            "99999999999999999999999",
                                            "0x10",
                                            "1.5",
                                            "1e3",
                                            "",
                                            "+",
                                            "-",
                                            "1,5",
                                            "\xd9\xa3",
                                            "1\0002"sv,
                                            "  "};

// Text that headers announce counts, versions, offsets and sizes after: a number right after
// one of these is a count or an index the reader must not trust.
const char* const kAnchors[] = {
    "$MeshFormat",    "$Nodes",        "$Elements",          "$Entities",   "MeshVersionFormatted",
    "Dimension",      "Vertices",      "Tetrahedra",         "Triangles",   "Edges",
    "NumberOfPoints", "NumberOfCells", "NumberOfComponents", "offset=",     "RangeMin",
    "RangeMax",       "<AppendedData", "<DataArray",         "\n$EndNodes", "\n"};

// Words the VTK header and the gmsh/Medit keywords are made of, and what else they could say.
const std::vector<std::vector<std::string>> kWordFamilies = {
    {"UInt64", "UInt32", "UInt8", "Int64", "Int32", "Int8", "Float32", "Float64", "String",
     "Bogus"},
    {"LittleEndian", "BigEndian", "MiddleEndian"},
    {"vtkZLibDataCompressor", "vtkLZ4DataCompressor", "vtkLZMADataCompressor", "NoCompressor"},
    {"appended", "binary", "ascii", "raw"},
    {"base64", "raw", "hex"},
    {"UnstructuredGrid", "PolyData", "ImageData"},
    {"connectivity", "offsets", "types", "Points"},
    {"$Nodes", "$Elements", "$EndNodes", "$EndElements", "$NOD", "$Entities", "$EndEntities"},
    {"Vertices", "Tetrahedra", "Triangles", "Hexahedra", "TetrahedraP2", "End", "Dimension"},
};

std::size_t find_nth(const std::string& text, const std::string& word, std::size_t nth) {
  std::size_t at = text.find(word);
  for (std::size_t i = 0; i < nth && at != std::string::npos; ++i) at = text.find(word, at + 1);
  return at;
}

template <class T>
std::string raw_bytes(T value) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &value, sizeof(T));
  return s;
}

// Binary fields of extreme value, 4 or 8 bytes, in this machine's byte order or swapped.
std::string hostile_binary(std::mt19937& rng) {
  const std::string values[] = {
      raw_bytes<std::int32_t>(-1),
      raw_bytes<std::int32_t>(0),
      raw_bytes<std::int32_t>(std::numeric_limits<std::int32_t>::max()),
      raw_bytes<std::int32_t>(std::numeric_limits<std::int32_t>::min()),
      raw_bytes<std::int32_t>(4),  // gmsh tet type, a block of 4...
      raw_bytes<std::int32_t>(1 << 24),
      raw_bytes<std::uint64_t>(std::numeric_limits<std::uint64_t>::max()),
      raw_bytes<std::uint64_t>(1ull << 40),
      raw_bytes<std::int64_t>(std::numeric_limits<std::int64_t>::max()),
      raw_bytes<std::int64_t>(-1),
      raw_bytes<double>(1e308),
      raw_bytes<double>(-1e308),
      raw_bytes<double>(std::numeric_limits<double>::quiet_NaN()),
      raw_bytes<double>(std::numeric_limits<double>::infinity()),
      raw_bytes<double>(std::numeric_limits<double>::denorm_min()),
      raw_bytes<float>(std::numeric_limits<float>::quiet_NaN()),
  };
  std::string v = values[rng() % std::size(values)];
  if (rng() % 2) std::reverse(v.begin(), v.end());
  return v;
}

// Wrapping arithmetic: the numbers come from mutated files (UBSan watches the test too).
long long wrapped(unsigned long long value) { return static_cast<long long>(value); }
long long plus(long long a, long long b) {
  return wrapped(static_cast<unsigned long long>(a) + static_cast<unsigned long long>(b));
}
long long times(long long a, long long b) {
  return wrapped(static_cast<unsigned long long>(a) * static_cast<unsigned long long>(b));
}

// One mutation of `text`, chosen by `rng`.
std::string mutate(std::string text, std::mt19937& rng) {
  auto pick = [&](std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  if (text.empty()) return text;
  switch (pick(14)) {
    case 0:  // bit flip
      text[pick(text.size())] ^= static_cast<char>(1u << pick(8));
      return text;
    case 1:  // truncation
      return text.substr(0, pick(text.size()));
    case 2: {  // a line deleted
      std::vector<std::string> lines = lines_of(text);
      lines.erase(lines.begin() + static_cast<long>(pick(lines.size())));
      return joined(lines);
    }
    case 3: {  // a line duplicated somewhere
      std::vector<std::string> lines = lines_of(text);
      const std::string copy = lines[pick(lines.size())];
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)), copy);
      return joined(lines);
    }
    case 4: {  // two lines swapped
      std::vector<std::string> lines = lines_of(text);
      std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
      return joined(lines);
    }
    case 5: {  // a number replaced by a hostile one
      const auto [b, e] = number_at(text, pick(text.size()));
      if (b == std::string::npos) return text;
      return text.replace(b, e - b, kHostileNumbers[pick(std::size(kHostileNumbers))]);
    }
    case 6: {  // an integer nudged: off-by-one indices, counts one too many or too few
      const auto [b, e] = number_at(text, pick(text.size()));
      if (b == std::string::npos) return text;
      const long long v = std::strtoll(text.substr(b, e - b).c_str(), nullptr, 10);
      const long long minus_v = times(v, -1);
      const long long deltas[] = {1, -1,        2,        -2, 1000, minus_v, plus(minus_v, -1),
                                  v, 1LL << 31, 1LL << 32};
      return text.replace(b, e - b, std::to_string(plus(v, deltas[pick(std::size(deltas))])));
    }
    case 7: {  // stray bytes inserted
      // NUL, bytes invalid in UTF-8, line ends, syntax characters, UTF-8 and UTF-16 marks.
      static const std::string_view kStray[] = {
          "\0"sv, "\xff", "\x80", "\r", "\n",           " ",        "$", "<", ">", "\"", "#",
          "_",    "=",    "-",    "e",  "\xef\xbb\xbf", "\xfe\xff", "\t"};
      text.insert(pick(text.size() + 1), kStray[pick(std::size(kStray))]);
      return text;
    }
    case 8: {  // a binary field overwritten with an extreme value
      const std::string v = hostile_binary(rng);
      if (text.size() < v.size()) return text;
      text.replace(pick(text.size() - v.size() + 1), v.size(), v);
      return text;
    }
    case 9: {  // a header count, version, offset or size that lies
      const std::string anchor = kAnchors[pick(std::size(kAnchors))];
      const std::size_t at = find_nth(text, anchor, pick(4));
      if (at == std::string::npos) return text;
      const auto [b, e] = number_at(text, at + anchor.size());
      if (b == std::string::npos) return text;
      const long long v = std::strtoll(text.substr(b, e - b).c_str(), nullptr, 10);
      std::string value;
      switch (pick(4)) {
        case 0:
          value = std::to_string(plus(v, pick(2) ? 1 : -1));
          break;
        case 1:
          value = std::to_string(times(v, static_cast<long long>(1 + pick(1000))));
          break;
        case 2:
          value = std::to_string(plus(times(v, -1), -1));
          break;
        default:
          value = kHostileNumbers[pick(std::size(kHostileNumbers))];
      }
      return text.replace(b, e - b, value);
    }
    case 10: {  // a header word replaced by another of its family (UInt64 -> UInt32, ...)
      const auto& family = kWordFamilies[pick(kWordFamilies.size())];
      const std::string& from = family[pick(family.size())];
      const std::size_t at = find_nth(text, from, pick(3));
      if (at == std::string::npos) return text;
      return text.replace(at, from.size(), family[pick(family.size())]);
    }
    case 11: {  // wrong encodings
      switch (pick(5)) {
        case 0: {  // CRLF line ends
          std::string out;
          for (char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
          return out;
        }
        case 1:  // a UTF-8 byte-order mark
          return "\xef\xbb\xbf" + text;
        case 2: {  // UTF-16LE (with its mark) of a prefix, the rest left as is
          const std::size_t n = std::min<std::size_t>(text.size(), 1 + pick(512));
          std::string out = "\xff\xfe";
          for (std::size_t i = 0; i < n; ++i) out += std::string(1, text[i]) + '\0';
          return out + text.substr(n);
        }
        case 3: {  // the blanks of one line turned into NULs
          std::vector<std::string> lines = lines_of(text);
          for (char& c : lines[pick(lines.size())])
            if (c == ' ') c = '\0';
          return joined(lines);
        }
        default: {  // Latin-1 bytes in place of letters of one line
          std::vector<std::string> lines = lines_of(text);
          for (char& c : lines[pick(lines.size())])
            if (std::isalpha(static_cast<unsigned char>(c)) && pick(3) == 0) c = '\xe9';
          return joined(lines);
        }
      }
    }
    case 12: {  // a byte range copied elsewhere (a block or section repeated, offsets shifted)
      const std::size_t from = pick(text.size());
      const std::size_t len = 1 + pick(std::min<std::size_t>(text.size() - from, 256));
      const std::string chunk = text.substr(from, len);
      text.insert(pick(text.size() + 1), chunk);
      return text;
    }
    default: {  // a byte range cut out
      const std::size_t from = pick(text.size());
      return text.erase(from, 1 + pick(std::min<std::size_t>(text.size() - from, 256)));
    }
  }
}

int env_or(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e[6] = {b - a, c - a, d - a, c - b, d - b, d - c};
  double longest2 = 0;
  for (const Vec3& v : e) longest2 = std::max(longest2, v.squaredNorm());
  return std::abs(6.0 * signed_volume(a, b, c, d)) / (longest2 * std::sqrt(longest2));
}

// What check_raw_mesh promises of every mesh it returns; "" when all holds.
std::string broken_promise(const TetMesh& m, const MeshReadReport& report) {
  const auto n = static_cast<std::int64_t>(m.points.size());
  if (m.tets.empty()) return "no tets";
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (!m.points[i].allFinite()) return cat("point ", i, " is not finite");
  std::vector<bool> used(m.points.size(), false);
  for (std::size_t k = 0; k < m.tets.size(); ++k) {
    const Tet& t = m.tets[k];
    for (int v : t)
      if (v < 0 || v >= n) return cat("tet ", k, " has index ", v, " of ", n, " points");
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (t[a] == t[b]) return cat("tet ", k, " uses a vertex twice");
    for (int v : t) used[static_cast<std::size_t>(v)] = true;
    const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]], &d = m.points[t[3]];
    const double v = signed_volume(a, b, c, d);
    if (!(v > 0) || !std::isfinite(v)) return cat("tet ", k, " has volume ", v);
    const double q = tet_quality(a, b, c, d);
    if (!(q >= kMinTetQuality)) return cat("tet ", k, " has quality ", q);
  }
  for (std::size_t i = 0; i < used.size(); ++i)
    if (!used[i]) return cat("point ", i, " is used by no tet");
  if (report.kept_vertices.size() != m.points.size()) return "report.kept_vertices size";
  if (report.reoriented_tets < 0 || report.reoriented_tets > static_cast<int>(m.tets.size()))
    return cat("report.reoriented_tets ", report.reoriented_tets);
  if (report.format.empty()) return "report.format is empty";
  return "";
}

// Keeps a failing input (and its TetGen partner) where the run can be reproduced from.
fs::path keep_failure(const Seed& s, const std::string& bytes, unsigned seed, int k) {
  const fs::path dir =
      fs::temp_directory_path() / "mrsim_mesh_fuzz_failures" / cat("seed", seed, "_input", k);
  std::error_code ec;
  fs::create_directories(dir, ec);
  write_file(dir / s.name, bytes);
  if (!s.partner.empty()) write_file(dir / s.partner, s.partner_bytes);
  return dir / s.name;
}

TEST(MeshFuzz, BundledMeshesLoad) {
  // The mutations start from meshes that load: otherwise every input would be refused.
  const std::vector<Seed> all = seeds();
  ASSERT_GE(all.size(), 15u);
  for (const Seed& s : all) {
    ScratchDir scratch;
    write_file(scratch / s.name, s.bytes);
    if (!s.partner.empty()) write_file(scratch / s.partner, s.partner_bytes);
    MeshReadReport report;
    const TetMesh m = read_tet_mesh(scratch / s.name, LengthUnit::Metre, &report);
    EXPECT_EQ(broken_promise(m, report), "") << s.name;
  }
}

// Reads one kept input again (MRSIM_FUZZ_REPLAY=path, e.g. from mrsim_mesh_fuzz_failures),
// under a debugger or a sanitizer build.
TEST(MeshFuzz, Replay) {
  const char* path = std::getenv("MRSIM_FUZZ_REPLAY");
  if (!path || !*path) GTEST_SKIP() << "set MRSIM_FUZZ_REPLAY to a mesh file to read it";
  try {
    MeshReadReport report;
    const TetMesh m = read_tet_mesh(path, LengthUnit::Metre, &report);
    std::printf("loaded %zu points, %zu tets\n", m.points.size(), m.tets.size());
    EXPECT_EQ(broken_promise(m, report), "");
  } catch (const InputError& e) {
    std::printf("input error: %s\n", e.what());
  }
}

TEST(MeshFuzz, MutatedBundledMeshesLoadOrAreInputErrors) {
  const std::vector<Seed> all = seeds();
  ASSERT_GE(all.size(), 15u);
  // Seeded: a few hundred inputs in ctest; scripts/fuzz_meshes.sh sets more, and other seeds.
  const int inputs = env_or("MRSIM_FUZZ_INPUTS", 400);
  const auto seed = static_cast<unsigned>(env_or("MRSIM_FUZZ_SEED", 20261127));
  // No input may come near a hang: the slowest honest read here takes milliseconds.
  const double slow_seconds = env_or("MRSIM_FUZZ_SLOW_SECONDS", 10);
  const bool verbose = env_or("MRSIM_FUZZ_VERBOSE", 0) != 0;  // every input's outcome
  std::mt19937 rng(seed);
  ScratchDir scratch;
  int loaded = 0, refused = 0, failed = 0;
  double slowest = 0;
  std::map<std::string, std::pair<int, int>> per_file;  // name -> loaded, refused
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < inputs; ++k) {
    const Seed& s = all[static_cast<std::size_t>(k) % all.size()];
    std::string bytes = s.bytes;
    const int rounds = 1 + k % 3;
    for (int r = 0; r < rounds; ++r) bytes = mutate(bytes, rng);
    const fs::path path = scratch / s.name;
    write_file(path, bytes);
    if (!s.partner.empty()) write_file(scratch / s.partner, s.partner_bytes);
    const LengthUnit unit = k % 5 == 4 ? LengthUnit::Millimetre : LengthUnit::Metre;
    if (verbose) {  // before the read: a crash leaves its input in the scratch folder
      std::printf("%d %s (%d mutations): ", k, s.name.c_str(), rounds);
      std::fflush(stdout);
    }
    std::string problem;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      MeshReadReport report;
      const TetMesh m = read_tet_mesh(path, unit, &report);
      ++loaded;
      ++per_file[s.name].first;
      problem = broken_promise(m, report);
      if (verbose) std::printf("loaded %zu points, %zu tets\n", m.points.size(), m.tets.size());
      if (!problem.empty()) problem = "loaded, but " + problem;
    } catch (const InputError& e) {
      ++refused;
      ++per_file[s.name].second;
      if (verbose) std::printf("%.200s\n", e.what());
      // Every mesh error starts with the path of the faulty file (TetGen: .node or .ele).
      if (std::string(e.what()).rfind(scratch.path().string() + "/", 0) != 0)
        problem = cat("InputError without the file path: ", e.what());
    } catch (const std::exception& e) {
      problem = cat("escaped as ", typeid(e).name(), ": ", e.what());
    } catch (...) {
      problem = "escaped as a non-standard exception";
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    slowest = std::max(slowest, seconds);
    if (problem.empty() && seconds > slow_seconds)
      problem = cat("took ", seconds, " s (a near-hang)");
    if (!problem.empty()) {
      ++failed;
      ADD_FAILURE() << "input " << k << " (" << s.name << ", seed " << seed << ", " << rounds
                    << " mutations): " << problem << "\n  kept as "
                    << keep_failure(s, bytes, seed, k).string();
    }
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "mesh fuzz: seed %u, %d inputs, %d loaded, %d refused with an input error, %d failed; "
      "%.1f s, slowest input %.3f s\n",
      seed, inputs, loaded, refused, failed, total, slowest);
  for (const auto& [name, n] : per_file)
    std::printf("  %-36s %6d loaded %6d refused\n", name.c_str(), n.first, n.second);
  if (inputs >= 200) {
    EXPECT_GT(refused, inputs / 4);  // the mutations do break meshes
    EXPECT_GT(loaded, inputs / 40);  // and some are harmless (the readers do not refuse all)
  }
}

}  // namespace
}  // namespace mrsim::test
