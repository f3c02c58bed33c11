/// @file compressed_check.cpp
/// @brief Finds where the compressed voxels start (after the NRRD or MetaImage header, or the whole file for
///        .nii.gz) and inflates them to their end with zlib.
#include "sim/bake_tool/compressed_check.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>

namespace lungar::sim {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// The value of "key: value" (NRRD) or "Key = Value" (MetaImage) header lines, lower case; nullopt if absent.
std::optional<std::string> header_value(const std::string& header, const std::string& key, char separator) {
  std::size_t at = 0;
  while (at < header.size()) {
    const std::size_t end = std::min(header.find('\n', at), header.size());
    const std::string line = header.substr(at, end - at);
    const std::size_t sep = line.find(separator);
    if (sep != std::string::npos && lower(line.substr(0, sep)).find(key) == 0 &&
        line.substr(0, sep).find_first_not_of(" \t", key.size()) == std::string::npos) {
      std::string value = line.substr(sep + 1);
      value.erase(0, value.find_first_not_of(" \t"));
      value.erase(value.find_last_not_of(" \t\r") + 1);
      return lower(value);
    }
    at = end + 1;
  }
  return std::nullopt;
}

/// Where the compressed voxels begin in `bytes`, or npos when the file keeps none of its own.
std::size_t compressed_start(const std::string& bytes) {
  if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b)
    return 0;  // the whole file is gzip (.nii.gz)
  if (bytes.rfind("NRRD", 0) == 0) {
    const std::size_t blank = bytes.find("\n\n");
    if (blank == std::string::npos) return std::string::npos;
    const std::string header = bytes.substr(0, blank);
    const auto encoding = header_value(header, "encoding", ':');
    const bool gzip = encoding && (*encoding == "gzip" || *encoding == "gz");
    const bool attached = !header_value(header, "data file", ':') && !header_value(header, "datafile", ':');
    return gzip && attached ? blank + 2 : std::string::npos;
  }
  const std::size_t local = lower(bytes.substr(0, 4096)).find("elementdatafile = local");
  if (local != std::string::npos) {
    const auto compressed = header_value(bytes.substr(0, local), "compresseddata", '=');
    const std::size_t eol = bytes.find('\n', local);
    return compressed && *compressed == "true" && eol != std::string::npos ? eol + 1 : std::string::npos;
  }
  return std::string::npos;
}

}  // namespace

lungar::Status check_compressed_voxels(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  const std::size_t start = compressed_start(bytes);
  if (start == std::string::npos) return ok();
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) return fail(path + ": voxels: zlib could not start");  // gzip or zlib
  z.next_in = reinterpret_cast<Bytef*>(bytes.data() + start);
  z.avail_in = static_cast<uInt>(bytes.size() - start);
  std::vector<Bytef> out(1 << 20);
  int rc = Z_OK;
  while (rc == Z_OK || (rc == Z_STREAM_END && z.avail_in > 0 && z.next_in[0] == 0x1f)) {  // gzip members in a row
    if (rc == Z_STREAM_END) inflateReset(&z);
    z.next_out = out.data();
    z.avail_out = static_cast<uInt>(out.size());
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc == Z_BUF_ERROR && z.avail_in == 0) break;  // the stream ends before its end: truncated
  }
  const std::string why = z.msg ? z.msg : rc == Z_STREAM_END ? "" : "the stream ends early";
  inflateEnd(&z);
  if (rc != Z_STREAM_END)
    return fail(path + ": voxels: the compressed data is damaged (zlib: " + why + "); expected an intact gzip stream");
  return ok();
}

}  // namespace lungar::sim
