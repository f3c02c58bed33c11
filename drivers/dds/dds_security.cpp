/// @file dds_security.cpp
/// @brief A station folder -> Cyclone's "dds.sec.*" participant properties.
#include "drivers/dds/dds_security.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <filesystem>

namespace lungar::dds {

namespace fs = std::filesystem;

Result<SecurityFiles> find_security_files(const std::string& dir) {
  const std::string where = "sync.security " + dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return fail(where + ": expected a station folder written by `lungar classroom-keys` (DIR/STATION/), got none");
  }
  SecurityFiles f;
  f.dir = fs::absolute(dir, ec).lexically_normal().string();
  const std::array<std::pair<const char*, std::string*>, 6> files{{{"identity_ca.pem", &f.identity_ca},
                                                                   {"identity_cert.pem", &f.identity_cert},
                                                                   {"identity_key.pem", &f.identity_key},
                                                                   {"permissions_ca.pem", &f.permissions_ca},
                                                                   {"governance.p7s", &f.governance},
                                                                   {"permissions.p7s", &f.permissions}}};
  for (const auto& [name, path] : files) {
    *path = (fs::path(f.dir) / name).string();
    if (::access(path->c_str(), R_OK) != 0) {
      return fail(where + ": expected " + name + " there (readable), got none: copy the station's whole folder");
    }
  }
  if (const fs::path crl = fs::path(f.dir) / "crl.pem"; fs::exists(crl, ec)) {
    if (::access(crl.c_str(), R_OK) != 0) return fail(where + ": crl.pem is there but not readable");
    f.crl = crl.string();
  }
  struct stat st {};
  if (::stat(f.identity_key.c_str(), &st) == 0 && (st.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    return fail(where +
                ": identity_key.pem is readable by others than its owner; expected mode 0600 "
                "(chmod 600 " +
                f.identity_key + ")");
  }
  return f;
}

std::string security_plugin_dir() { return LUNGAR_DDS_SECURITY_DIR; }

Status add_security_properties(const SecurityFiles& f, std::uint32_t domain, dds::Qos& qos) {
  if (domain > 230) {
    return fail(
        "sync.domain: a secure classroom needs a DDS domain id in [0, 230] (what a governance document "
        "can name), got " +
        std::to_string(domain));
  }
  const std::string plugins = security_plugin_dir();
  for (const char* lib : {"libdds_security_auth.so", "libdds_security_ac.so", "libdds_security_crypto.so"}) {
    if (plugins.empty() || ::access((fs::path(plugins) / lib).c_str(), R_OK) != 0) {
      return fail("sync.security: Cyclone DDS's security plugin " + std::string(lib) + " is not installed" +
                  (plugins.empty() ? std::string() : " in " + plugins) + " (Debian package libddsc0debian)");
    }
  }
  const auto file = [](const std::string& path) { return "file:" + path; };
  qos.property("dds.sec.auth.library.path", plugins + "/libdds_security_auth.so")
      .property("dds.sec.auth.library.init", "init_authentication")
      .property("dds.sec.auth.library.finalize", "finalize_authentication")
      .property("dds.sec.access.library.path", plugins + "/libdds_security_ac.so")
      .property("dds.sec.access.library.init", "init_access_control")
      .property("dds.sec.access.library.finalize", "finalize_access_control")
      .property("dds.sec.crypto.library.path", plugins + "/libdds_security_crypto.so")
      .property("dds.sec.crypto.library.init", "init_crypto")
      .property("dds.sec.crypto.library.finalize", "finalize_crypto")
      .property("dds.sec.auth.identity_ca", file(f.identity_ca))
      .property("dds.sec.auth.identity_certificate", file(f.identity_cert))
      .property("dds.sec.auth.private_key", file(f.identity_key))
      .property("dds.sec.access.permissions_ca", file(f.permissions_ca))
      .property("dds.sec.access.governance", file(f.governance))
      .property("dds.sec.access.permissions", file(f.permissions));
  // Cyclone's own property (the OMG specification has none for revocation): its authentication plugin checks
  // every identity, its own and its peers', against this list.
  if (!f.crl.empty()) qos.property("org.eclipse.cyclonedds.sec.auth.crl", file(f.crl));
  return ok();
}

}  // namespace lungar::dds
