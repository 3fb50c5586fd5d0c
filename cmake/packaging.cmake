# cpack, from the install rules above: a Debian package (/usr/bin,
# /usr/lib/marchstudio, /usr/share/marchstudio) and a relocatable .tar.gz
# (the same tree under marchstudio-VERSION-Linux/). Both are the install
# tree, which finds its modules and GLSL library relative to the binary.
#   cd build && cpack            # both, into build/
#   cpack -G DEB                 # one
# docs/packages.md; ctest's package test (tests/install/check_package.py)
# builds, unpacks and runs them.
set(MARCH_PACKAGE_CONTACT "marchstudio maintainers" CACHE STRING
    "The packages' maintainer (Debian's Maintainer field)")

set(CPACK_PACKAGE_NAME marchstudio)
set(CPACK_PACKAGE_VENDOR marchstudio)
set(CPACK_PACKAGE_CONTACT "${MARCH_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "SDF raymarching studio: headless renders, image and cost tests, meshes")
set(CPACK_PACKAGE_DESCRIPTION
    "marchstudio renders signed distance field scenes, Shadertoy and glslViewer shaders headless (llvmpipe or a GPU through EGL), tests them against reference images and cost budgets (marchstudio test), exports meshes and OpenVDB level sets, and views them live.")
set(CPACK_GENERATOR "DEB;TGZ")
set(CPACK_STRIP_FILES ON)
# The install rules hold one tree (no components): the archive is that tree.
set(CPACK_ARCHIVE_COMPONENT_INSTALL OFF)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # marchstudio_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# What the binary and the two modules link, from dpkg-shlibdeps (dpkg-dev,
# which build-essential brings) ...
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# ... and what they dlopen, which it cannot see: OSMesa (the default
# headless context), Mesa's EGL vendor and llvmpipe driver (EGL
# surfaceless), libsndfile (Shadertoy music inputs).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libosmesa6, libegl-mesa0, libgl1-mesa-dri, libsndfile1")
# render --video and video inputs run ffmpeg; the viewer plays music through ALSA.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg, libasound2")

include(CPack)
