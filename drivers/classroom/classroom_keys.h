/// @file classroom_keys.h
/// @brief `lungar classroom-keys`: the keys and signed documents of a secure classroom (OMG DDS Security, which
///        Debian's Cyclone DDS ships as plugins): a certificate authority for the classroom, one identity per
///        station signed by it, the signed governance (what is protected: discovery, liveliness and every topic's
///        data, encrypted; no unauthenticated participant) and the signed permissions (the instructor alone may
///        publish the patient pose, the breath, the scenario and the heartbeat; every station its own status and
///        its clock requests; all of it within the classroom's partition). Made with Debian's `openssl` command, no
///        crypto of our own.
///
/// `DIR/ca/` holds the authority (its key stays there, mode 0600: keep it off the classroom's machines);
/// `DIR/<station>/` is everything that station needs, self-contained: identity_ca.pem, identity_cert.pem,
/// identity_key.pem (0600), permissions_ca.pem, governance.p7s, permissions.p7s.
/// `DIR/console/` is the instructor's console (platform/console/), for the instructor station:
/// server_cert.pem (an HTTPS server certificate signed by the authority, for localhost, 127.0.0.1 and each
/// --console-host), server_key.pem (0600), ca.pem (the authority's certificate, for the browsers to trust), logins
/// (an `instructor` and an `observer` login: PBKDF2 hashes, platform/console/console_logins.h) and their random
/// passwords, instructor.password and observer.password (0600), for the trainer. A station's identity is never a
/// console login.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::classroom {

struct ClassroomKeysOptions {
  std::string classroom;              ///< the classroom's name: the DDS partition, and the certificates' OU
  std::vector<std::string> stations;  ///< station names (one folder each)
  std::string instructor;             ///< which station teaches; empty: the first
  std::string out_dir;                ///< must not exist, or be empty: written whole or not at all
  std::string ca_dir;                 ///< reuse this authority (ca_cert.pem, ca_key.pem) instead of making one
  /// Names the console's certificate is valid for besides localhost and 127.0.0.1: each an IP address or a DNS name
  /// by which the trainer's tablet reaches the instructor station.
  std::vector<std::string> console_hosts;
  int days = 365;                     ///< validity of the certificates and the permissions
  std::string openssl = "openssl";    ///< the command (tests point it elsewhere to see a failure)
};

/// One line per station (and for the console) of what to copy where, or the error (one line; nothing left in
/// out_dir).
Result<std::vector<std::string>> make_classroom_keys(const ClassroomKeysOptions& o);

/// `lungar classroom-revoke`: the authority withdraws a station's identity (a lost or stolen HMD PC).
struct ClassroomRevokeOptions {
  std::string ca_dir;              ///< the authority's folder (DIR/ca of classroom-keys): its list of revoked grows
  std::vector<std::string> certs;  ///< identity_cert.pem of each station to revoke
  std::string openssl = "openssl";
};

/// Revokes `certs` (each checked as issued by this authority) and writes the authority's certificate revocation
/// list, CA_DIR/crl.pem, naming every certificate it revoked so far; returns the line that says where to copy it
/// (each station's folder, as crl.pem: a station with it refuses the revoked ones). Nothing changes on an error.
Result<std::string> revoke_classroom_stations(const ClassroomRevokeOptions& o);

/// The permissions document (unsigned) and the governance document: what make_classroom_keys signs.
std::string classroom_permissions_xml(const ClassroomKeysOptions& o, const std::string& not_before,
                                      const std::string& not_after);
std::string classroom_governance_xml();

/// The topics a role may publish (instructor: every classroom topic it writes; trainee: its station, its status
/// for the console and its clock requests).
std::vector<std::string> topics_published_by(bool instructor);

}  // namespace lungar::classroom
