# The Debian package of vplab (README "Install"): `cpack -G DEB` in the build tree, or scripts/package.sh,
# makes vplab_VERSION_ARCH.deb of what `cmake --install` installs (app/CMakeLists.txt), under /usr.
#
# Its dependencies: the shared libraries vplab links are found by dpkg-shlibdeps (never written here by
# hand); what vplab loads at run time without linking it is named below, because no tool can see it:
#   libegl1, libegl-mesa0   `vplab render`'s EGL (glad loads libEGL.so.1) and Mesa's EGL vendor library
#   libgl1, libglx-mesa0    the window's OpenGL through GLX (GLFW loads libGL.so.1), Mesa's GLX
#   libgl1-mesa-dri         Mesa's drivers, llvmpipe among them: vplab draws on a machine with no GPU
#   fonts-dejavu-core       DejaVu Sans, the one font of the views' labels and the panels
#                           (app/fonts/font_file.h)
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "vplab")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "${VPLAB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Viewing Pipeline Lab: the 3D viewing pipeline, interactive")
# The extended description, wrapped at 78 columns as lintian wants (CPack prefixes each line with a space,
# an empty line becomes " .").
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "vplab is a teaching viewer for the 3D viewing pipeline of a computer graphics"
  "course. A synthetic camera (view reference point, projection reference point,"
  "view-up vector, a window, front and back planes) maps a scene through"
  "modeling, view orientation, view mapping, clipping in homogeneous coordinates"
  "and device mapping; the world, camera and NPC views show every stage, and"
  "sliders and handles change the camera while the class watches."
  ""
  "Course staff run it headless: vplab render draws the views as PNG or SVG,"
  "vplab dump writes every stage's values, vplab exercise makes exercise sheets"
  "with per-student variants and vplab grade marks the answers of a class. It"
  "draws with OpenGL on Mesa's llvmpipe, so a lab machine needs no GPU."
)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # vplab_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "education")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libegl-mesa0, libgl1, libglx-mesa0, libgl1-mesa-dri, fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)  # 0644 control files, as dpkg and lintian want
set(CPACK_STRIP_FILES ON)  # no debugging symbols in the installed binary (Debian's policy 10.1)
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
include(CPack)
