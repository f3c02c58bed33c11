# The Debian package (CPack's DEB generator; scripts/package drives it): what cmake --install puts under /usr,
# dependencies from dpkg-shlibdeps, a post-install that reloads the udev rules. No conffiles and no files outside
# /usr, so `apt-get remove` leaves nothing behind but what users made themselves.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME lungar)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the lungar developers")
set(CPACK_PACKAGE_CONTACT "lungar developers <lungar@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "breathing 3-D lungs on a patient simulator, for a head-mounted display")
# Wrapped below 80 columns, as Debian's control files want.
set(CPACK_PACKAGE_DESCRIPTION
  "lungar superimposes breathing 3-D lungs on a human patient simulator seen
through a head-mounted display. It reads head and patient-tracker poses over
USB HID, turns the patient's orientation into the applied force in
spherical-harmonic form, and deforms the lung surface in the vertex shader
(Santhanam, Hamza-Lup and Rolland, IEEE TITB 2007), for stereo point rendering
on OpenGL ES 3.0 through EGL.
This package holds the runtime (lungar, with lungar doctor), the offline baker
(lungar-bake), the tracker-log tool (lungar-trk), the profiles and teaching
scenarios, the tracker udev rules and a systemd user unit.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)                 # lungar_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)                  # Depends: from dpkg-shlibdeps
set(CPACK_DEBIAN_PACKAGE_DEPENDS "openssl")             # and the command lungar classroom-keys runs
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/scripts/debian/postinst)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)  # postinst 0755, whatever the checkout's mode
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
  OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
include(CPack)
