/// @file pose_sample.cpp
/// @brief Role names as they are spelled in config and logs.
#include "drivers/pose/pose_sample.h"

namespace lungar::drivers {

const char* to_string(Role role) {
  switch (role) {
    case Role::Head: return "head";
    case Role::Patient: return "patient";
    case Role::Stylus: return "stylus";
  }
  return "?";
}

std::optional<Role> role_from_string(std::string_view name) {
  for (Role r : kRoles) {
    if (name == to_string(r)) return r;
  }
  return std::nullopt;
}

}  // namespace lungar::drivers
