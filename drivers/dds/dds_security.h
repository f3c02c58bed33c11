/// @file dds_security.h
/// @brief A secure classroom's participant: the station folder that `lungar classroom-keys` wrote, checked, and
/// turned into the participant properties that switch on Cyclone's DDS Security plugins (authentication by
/// the classroom's authority, access control by the signed governance and permissions, encryption).
/// @ingroup platform
///
/// Security is per participant, set through its QoS (the "dds.sec.*" properties of the OMG DDS Security
/// specification), so that the shipped Cyclone XML stays one file for open and secure classrooms alike.
#pragma once

#include <cstdint>
#include <string>

#include "config/base/result.h"
#include "drivers/dds/dds.h"

namespace lungar::dds {

/// The six files of a station's folder, as absolute paths.
struct SecurityFiles {
  std::string dir;
  std::string identity_ca, identity_cert, identity_key;
  std::string permissions_ca, governance, permissions;
  std::string crl;  ///< crl.pem, the authority's revocation list, when the folder has one ("" otherwise)
};

/// Checks `dir` (a station folder of `lungar classroom-keys`): each file there and readable, the private key
/// readable by its owner alone (as ssh insists: a key others can read is a key others may have copied).
/// A crl.pem there (from `lungar classroom-revoke`) makes the station refuse the identities it lists.
/// The error names the folder, the file and what to do.
Result<SecurityFiles> find_security_files(const std::string& dir);

/// Where Cyclone's security plugins (libdds_security_auth.so, _ac, _crypto) live: Debian's libddsc0debian
/// folder, found when lungar was built; empty when they were not there.
std::string security_plugin_dir();

/// Adds to `qos` the properties that switch security on with `files`; an error when the plugins are missing or
/// the domain is outside what a governance document can name (0 to 230).
Status add_security_properties(const SecurityFiles& files, std::uint32_t domain, dds::Qos& qos);

}  // namespace lungar::dds
