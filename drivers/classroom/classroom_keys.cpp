/// @file classroom_keys.cpp
/// @brief The authority, the identities and the signed documents of classroom_keys.h, through `openssl`.
#include "drivers/classroom/classroom_keys.h"

#include "drivers/classroom/console_login_line.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include "config/base/atomic_file.h"

extern char** environ;

namespace lungar::classroom {
namespace fs = std::filesystem;

namespace {

/// Runs `openssl args...`; an error carries openssl's last line of stderr.
Status openssl(const ClassroomKeysOptions& o, const std::vector<std::string>& args, const fs::path& scratch) {
  std::vector<std::string> argv{o.openssl};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> c;
  for (std::string& a : argv) c.push_back(a.data());
  c.push_back(nullptr);
  const std::string err = (scratch / "openssl.err").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int e = posix_spawnp(&pid, o.openssl.c_str(), &actions, nullptr, c.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (e != 0) return fail(o.openssl + ": cannot start it (" + std::strerror(e) + "): install Debian's openssl");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return fail(o.openssl + ": cannot wait for it: " + std::strerror(errno));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return ok();
  std::ifstream in(err);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return fail(o.openssl + " " + args.front() + " failed: " + (last.empty() ? "no message" : last));
}

std::string utc(std::chrono::system_clock::time_point t) {
  const std::time_t s = std::chrono::system_clock::to_time_t(t);
  std::tm tm{};
  gmtime_r(&s, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

/// The subject of a station's certificate, in the order DDS Security compares (RFC 2253, most specific first).
std::string subject_of(const std::string& classroom, const std::string& station) {
  return "CN=" + station + ",OU=" + classroom + ",O=lungar";
}

Status check_name(const std::string& what, const std::string& name) {
  const bool ok_chars = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
  if (name.empty() || name.size() > 63 || !ok_chars || name[0] == '.')
    return fail(what + ": expected 1 to 63 letters, digits, '-', '_' or '.' (not first), got \"" + name + "\"");
  return ok();
}

/// Whether `host` is an IPv4 or IPv6 address (then "IP:host" in a certificate's names), else a DNS name.
bool is_ip(const std::string& host) {
  unsigned char buf[16];
  return inet_pton(AF_INET, host.c_str(), buf) == 1 || inet_pton(AF_INET6, host.c_str(), buf) == 1;
}

/// A DNS name as a certificate names a host: dot-separated labels of letters, digits and '-' (not at a label's
/// ends), each 1 to 63 long, 253 in all. Nothing else may reach the openssl configuration it is written into.
bool is_dns_name(const std::string& host) {
  if (host.empty() || host.size() > 253) return false;
  std::size_t start = 0;
  while (start <= host.size()) {
    const std::size_t end = std::min(host.find('.', start), host.size());
    const std::string label = host.substr(start, end - start);
    if (label.empty() || label.size() > 63 || label.front() == '-' || label.back() == '-') return false;
    if (!std::all_of(label.begin(), label.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; }))
      return false;
    start = end + 1;
  }
  return true;
}

/// Writes `text` to `path` with mode 0600 (a private key's or a password's).
Status write_private(const fs::path& path, const std::string& text) {
  if (Status s = write_file_atomically(path.string(), text); !s) return s;
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  return ok();
}

/// DIR/console: the console's HTTPS certificate signed by the authority, its key, the authority's certificate for
/// the browsers, the logins and their passwords.
Status make_console(const ClassroomKeysOptions& o, const fs::path& dir, const std::string& ca_cert,
                    const std::string& ca_key, std::uint64_t serial) {
  const fs::path c = dir / "console";
  fs::create_directories(c);
  std::vector<std::string> names{"DNS:localhost", "IP:127.0.0.1"};
  for (const std::string& host : o.console_hosts) {
    const std::string name = (is_ip(host) ? "IP:" : "DNS:") + host;
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  std::string san;
  for (const std::string& n : names) san += (san.empty() ? "" : ", ") + n;
  const fs::path ext = dir / "console.ext", csr = c / "server.csr";
  if (Status s = write_file_atomically(ext.string(),
                                       "[server]\nbasicConstraints = critical, CA:FALSE\n"
                                       "keyUsage = critical, digitalSignature\nextendedKeyUsage = serverAuth\n"
                                       "subjectKeyIdentifier = hash\nauthorityKeyIdentifier = keyid, issuer\n"
                                       "subjectAltName = " +
                                           san + "\n");
      !s)
    return s;
  const std::string key = (c / "server_key.pem").string();
  if (Status r =
          openssl(o,
                  {"req", "-new", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key,
                   "-out", csr.string(), "-subj", "/O=lungar/OU=" + o.classroom + "/CN=lungar console"},
                  dir);
      !r)
    return r;
  fs::permissions(key, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  if (Status r = openssl(o,
                         {"x509", "-req", "-in", csr.string(), "-CA", ca_cert, "-CAkey", ca_key, "-set_serial",
                          std::to_string(serial), "-days", std::to_string(o.days), "-extfile", ext.string(),
                          "-extensions", "server", "-out", (c / "server_cert.pem").string()},
                         dir);
      !r)
    return r;
  fs::remove(csr);
  fs::remove(ext);
  fs::copy_file(ca_cert, c / "ca.pem");
  std::string logins = "# the console's logins (lungar classroom-keys): NAME ROLE pbkdf2-sha256 ITERATIONS SALT HASH\n";
  for (const char* role : {"instructor", "observer"}) {
    auto password = random_password(20);
    if (!password) return password.with_context("");
    auto line = make_login_line(role, role, *password);
    if (!line) return line.with_context("");
    logins += *line + "\n";
    if (Status s = write_private(c / (std::string(role) + ".password"), *password + "\n"); !s) return s;
  }
  return write_private(c / "logins", logins);
}

/// Everything into `dir` (a fresh folder); the caller renames it into place.
Result<std::vector<std::string>> make_into(const ClassroomKeysOptions& o, const fs::path& dir) {
  const fs::path ca = dir / "ca";
  fs::create_directories(ca);
  const std::string days = std::to_string(o.days);
  const std::string ca_cert = (ca / "ca_cert.pem").string(), ca_key = (ca / "ca_key.pem").string();
  if (o.ca_dir.empty()) {
    if (Status s = openssl(o,
                           {"req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
                            "-keyout", ca_key, "-out", ca_cert, "-days", days, "-subj",
                            "/O=lungar/OU=" + o.classroom + "/CN=" + o.classroom + " authority"},
                           dir);
        !s)
      return s.with_context("the classroom's authority: ");
  } else {
    for (const char* f : {"ca_cert.pem", "ca_key.pem"}) {
      std::error_code ec;
      fs::copy_file(fs::path(o.ca_dir) / f, ca / f, ec);
      if (ec) return fail("--ca " + o.ca_dir + ": " + f + ": cannot copy it: " + ec.message());
    }
  }
  fs::permissions(ca_key, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  const auto now = std::chrono::system_clock::now();
  const std::string not_before = utc(now - std::chrono::hours(1)),
                    not_after = utc(now + std::chrono::hours(24 * o.days));
  if (Status s = write_file_atomically((dir / "governance.xml").string(), classroom_governance_xml()); !s)
    return s.with_context("");
  if (Status s = write_file_atomically((dir / "permissions.xml").string(),
                                       classroom_permissions_xml(o, not_before, not_after));
      !s)
    return s.with_context("");
  for (const char* doc : {"governance", "permissions"}) {
    if (Status s = openssl(o,
                           {"smime", "-sign", "-text", "-in", (dir / (std::string(doc) + ".xml")).string(), "-out",
                            (dir / (std::string(doc) + ".p7s")).string(), "-signer", ca_cert, "-inkey", ca_key},
                           dir);
        !s)
      return s.with_context(std::string("the ") + doc + " document: ");
  }
  std::mt19937_64 rng(std::random_device{}());
  std::vector<std::string> lines;
  for (const std::string& station : o.stations) {
    const fs::path s = dir / station;
    fs::create_directories(s);
    const std::string key = (s / "identity_key.pem").string(), csr = (s / "identity.csr").string();
    if (Status r = openssl(o,
                           {"req", "-new", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
                            "-keyout", key, "-out", csr, "-subj", "/O=lungar/OU=" + o.classroom + "/CN=" + station},
                           dir);
        !r)
      return r.with_context("station " + station + ": ");
    fs::permissions(key, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
    if (Status r = openssl(o,
                           {"x509", "-req", "-in", csr, "-CA", ca_cert, "-CAkey", ca_key, "-set_serial",
                            std::to_string(rng() >> 2), "-days", days, "-out", (s / "identity_cert.pem").string()},
                           dir);
        !r)
      return r.with_context("station " + station + ": ");
    fs::remove(csr);
    for (const char* copy : {"identity_ca.pem", "permissions_ca.pem"}) fs::copy_file(ca_cert, s / copy);
    for (const char* doc : {"governance.p7s", "permissions.p7s"}) fs::copy_file(dir / doc, s / doc);
    const bool teaches = station == o.instructor;
    lines.push_back("station " + station + " (" + (teaches ? "instructor" : "trainee") + "): copy " +
                    (fs::path(o.out_dir) / station).string() + "/ to its HMD PC (its identity, the authority's " +
                    "certificate, the signed governance and permissions)");
  }
  if (Status c = make_console(o, dir, ca_cert, ca_key, rng() >> 2); !c) return c.with_context("the console: ");
  const std::string console = (fs::path(o.out_dir) / "console").string();
  lines.push_back("console: copy " + console + "/ to the instructor station (lungar --console); give the trainer " +
                  console + "/instructor.password and observer.password (logins instructor and observer); each " +
                  "browser imports " + console + "/ca.pem as an authority");
  fs::remove(dir / "openssl.err");
  lines.push_back("keep " + (fs::path(o.out_dir) / "ca").string() +
                  "/ (the authority's private key) off the classroom's machines; --ca reuses it for new stations");
  return lines;
}

}  // namespace

Result<std::string> revoke_classroom_stations(const ClassroomRevokeOptions& given) {
  ClassroomKeysOptions o;  // openssl() reads the command from it
  o.openssl = given.openssl;
  const fs::path ca(given.ca_dir);
  const std::string ca_cert = (ca / "ca_cert.pem").string(), ca_key = (ca / "ca_key.pem").string();
  for (const std::string& f : {ca_cert, ca_key})
    if (!fs::exists(f))
      return fail("--ca " + given.ca_dir + ": expected " + fs::path(f).filename().string() + " there");
  if (given.certs.empty()) return fail("--cert: expected at least one station's identity_cert.pem");
  for (const std::string& c : given.certs) {
    if (!fs::exists(c)) return fail("--cert " + c + ": no such file (a station's identity_cert.pem)");
    if (Status v = openssl(o, {"verify", "-CAfile", ca_cert, c}, ca); !v) {
      fs::remove(ca / "openssl.err");
      return fail("--cert " + c + ": not a certificate of this authority (" + v.error() + ")");
    }
  }
  // openssl's small CA database beside the authority's key: the list of what it revoked, kept across runs.
  const fs::path index = ca / "index.txt", crlnumber = ca / "crlnumber", cnf = ca / "openssl-ca.cnf";
  std::error_code ec;
  if (!fs::exists(index)) std::ofstream(index).flush();
  if (!fs::exists(crlnumber)) std::ofstream(crlnumber) << "01\n";
  std::ofstream(cnf) << "[ ca ]\ndefault_ca = classroom\n[ classroom ]\ndatabase = " << index.string()
                     << "\ncrlnumber = " << crlnumber.string()
                     << "\ndefault_md = sha256\ndefault_crl_days = 3650\nunique_subject = no\n";
  const std::string backup = index.string() + ".before";
  fs::copy_file(index, backup, fs::copy_options::overwrite_existing, ec);
  const auto restore = [&](const std::string& why) -> Result<std::string> {
    fs::rename(backup, index, ec);
    fs::remove(ca / "openssl.err", ec);
    return fail(why);
  };
  for (const std::string& c : given.certs) {
    if (Status r = openssl(o, {"ca", "-config", cnf.string(), "-keyfile", ca_key, "-cert", ca_cert, "-revoke", c}, ca);
        !r && r.error().find("lready revoked") == std::string::npos)
      return restore("--cert " + c + ": " + r.error());
  }
  const std::string crl_new = (ca / "crl.pem.new").string();
  if (Status g = openssl(
          o, {"ca", "-config", cnf.string(), "-keyfile", ca_key, "-cert", ca_cert, "-gencrl", "-out", crl_new}, ca);
      !g)
    return restore("the revocation list: " + g.error());
  fs::rename(crl_new, ca / "crl.pem", ec);
  if (ec) return restore((ca / "crl.pem").string() + ": cannot write it: " + ec.message());
  fs::remove(backup, ec);
  fs::remove(ca / "openssl.err", ec);
  return "copy " + (ca / "crl.pem").string() +
         " into every station's folder (as crl.pem): from its next start, a station refuses the revoked identities";
}

std::vector<std::string> topics_published_by(bool instructor) {
  if (instructor)
    return {"lungar_station",         "lungar_patient_pose", "lungar_breathing_state",
            "lungar_scenario_events", "lungar_heartbeat",    "lungar_time_reply"};
  return {"lungar_station", "lungar_time_request", "lungar_station_status"};
}

std::string classroom_governance_xml() {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- Written by `lungar classroom-keys`: what a lungar classroom protects. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>230</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
)";
}

std::string classroom_permissions_xml(const ClassroomKeysOptions& o, const std::string& not_before,
                                      const std::string& not_after) {
  const std::string instructor = o.instructor.empty() && !o.stations.empty() ? o.stations.front() : o.instructor;
  std::string x = R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- Written by `lungar classroom-keys`: who may publish what in classroom ")" +
                  o.classroom + R"(". -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
)";
  for (const std::string& station : o.stations) {
    x += "    <grant name=\"" + o.classroom + "." + station + "\">\n";
    x += "      <subject_name>" + subject_of(o.classroom, station) + "</subject_name>\n";
    x += "      <validity><not_before>" + not_before + "</not_before><not_after>" + not_after +
         "</not_after></validity>\n";
    x += "      <allow_rule>\n        <domains><id_range><min>0</min><max>230</max></id_range></domains>\n";
    x += "        <publish>\n          <topics>\n";
    for (const std::string& t : topics_published_by(station == instructor))
      x += "            <topic>" + t + "</topic>\n";
    x += "          </topics>\n          <partitions><partition>" + o.classroom + "</partition></partitions>\n";
    x += "        </publish>\n        <subscribe>\n          <topics><topic>lungar_*</topic></topics>\n";
    x += "          <partitions><partition>" + o.classroom + "</partition></partitions>\n        </subscribe>\n";
    x += "      </allow_rule>\n      <default>DENY</default>\n    </grant>\n";
  }
  return x + "  </permissions>\n</dds>\n";
}

Result<std::vector<std::string>> make_classroom_keys(const ClassroomKeysOptions& given) {
  ClassroomKeysOptions o = given;
  if (Status s = check_name("--classroom", o.classroom); !s) return s.with_context("");
  if (o.stations.empty()) return fail("--station: expected at least one station");
  std::set<std::string> seen;
  for (const std::string& s : o.stations) {
    if (Status c = check_name("--station", s); !c) return c.with_context("");
    if (s == "ca") return fail("--station: \"ca\" is the authority's folder; name the station otherwise");
    if (s == "console") return fail("--station: \"console\" is the console's folder; name the station otherwise");
    if (!seen.insert(s).second) return fail("--station: \"" + s + "\" given twice");
  }
  if (o.instructor.empty()) o.instructor = o.stations.front();
  if (!seen.count(o.instructor))
    return fail("--instructor: expected one of the --station names, got \"" + o.instructor + "\"");
  for (const std::string& host : o.console_hosts)
    if (!is_ip(host) && !is_dns_name(host))
      return fail("--console-host: expected an IP address or a DNS name (letters, digits, '-', dots), got \"" + host +
                  "\"");
  if (o.days < 1 || o.days > 3650) return fail("--days: expected 1 to 3650, got " + std::to_string(o.days));
  if (!o.ca_dir.empty()) {
    for (const char* f : {"ca_cert.pem", "ca_key.pem"})
      if (!fs::exists(fs::path(o.ca_dir) / f)) return fail("--ca " + o.ca_dir + ": expected " + f + " there");
  }
  // "keys/" (as a shell completes it) names the folder keys: without the slash its parent is where the work
  // folder goes, beside it, and not inside it.
  fs::path out = fs::path(o.out_dir).lexically_normal();
  while (!out.has_filename() && out.has_relative_path()) out = out.parent_path();
  std::error_code ec;
  const bool out_existed = fs::exists(out, ec);
  if (out_existed && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
    return fail(o.out_dir + ": expected a new or empty folder (nothing is overwritten)");
  const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  const fs::path work = parent / (".keys-" + std::to_string(getpid()));
  // The first folder this run makes on the way to the work folder: on a failure it goes, with all it holds, so that
  // a retry finds things as they were.
  fs::path first_made = work;
  for (fs::path p = parent; !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    first_made = p;
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec) {
    fs::remove_all(first_made, ec);
    return fail(work.string() + ": cannot make it: " + ec.message());
  }
  fs::permissions(work, fs::perms::owner_all, fs::perm_options::replace, ec);
  // make_into's folder work (create, copy, chmod) throws on a full disk or a read-only place: one line too.
  Result<std::vector<std::string>> made = fail("");
  try {
    made = make_into(o, work);
  } catch (const fs::filesystem_error& e) {
    made = fail(o.out_dir + ": " + e.what());
  }
  if (!made) {
    fs::remove_all(first_made, ec);
    return made.with_context("");
  }
  if (out_existed) fs::remove(out, ec);  // the empty folder it replaces
  fs::rename(work, out, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove_all(first_made, ec);
    if (out_existed) fs::create_directory(out, ec);  // the user's empty folder, as it was
    return fail(o.out_dir + ": cannot put the keys there: " + why);
  }
  return made;
}

}  // namespace lungar::classroom
