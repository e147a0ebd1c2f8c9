# Third-party packages, all from Debian 12. Each workaround names its section of docs/pitfalls.md.
set(CMAKE_AUTOMOC ON)
set(CMAKE_AUTORCC ON)

find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Concurrent Svg Test LinguistTools)

# docs/pitfalls.md, "Eigen config package": CGAL ships a FindEigen3 module without Eigen3::Eigen; ask for the config package.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CGAL REQUIRED)

# VTK serves views/ and the editor only (CELFORM_BUILD_EDITOR).
if(CELFORM_BUILD_EDITOR)
  # docs/pitfalls.md, "VTK and MPI": VTK 9.1's targets reference MPI::MPI_C.
  find_package(MPI COMPONENTS C)
  find_package(VTK REQUIRED COMPONENTS
    CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
    RenderingCore RenderingOpenGL2 RenderingImage InteractionStyle FiltersCore FiltersSources)
endif()

# docs/pitfalls.md, "OpenImageIO tools" (needs openimageio-tools installed) and "OpenImageIO include
# path" (drop the opencv4 include path).
find_package(OpenImageIO REQUIRED)
get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
if(_oiio_inc)
  list(FILTER _oiio_inc EXCLUDE REGEX "opencv4")
  set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_inc}")
endif()

find_package(assimp REQUIRED)
find_package(ZLIB REQUIRED)
# Rendered frames to PNG: libdeflate compresses the filtered rows (io/png_encoder.h; Debian:
# libdeflate-dev, which ships a pkg-config file and no CMake package).
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)
# Rendered frames to EXR: OpenEXR's core library writes the container, libdeflate compresses the
# chunks (io/exr_encoder.h; Debian: libopenexr-dev).
find_package(OpenEXR 3 CONFIG REQUIRED)
find_package(tinyobjloader REQUIRED)
# glTF 2.0 animated bases (skins, morph targets) and export (Debian: libtinygltf-dev).
find_package(TinyGLTF REQUIRED)
