# The web build (emcmake cmake -DS4D_WEB=ON, scripts/build-web.sh): the same layers compiled by
# Debian's emscripten into one page. Debian's emscripten finds nothing of /usr, and its ports
# download sources (unavailable offline), so the header-only libraries come from a private include
# folder of links into /usr/include (never -I/usr/include itself: its libc headers are not the
# page's), and Dear ImGui's sources from Debian's imgui source package (S4D_IMGUI_SOURCE_DIR).
set(S4D_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${S4D_WEB_INCLUDE})
foreach(pair "Eigen=/usr/include/eigen3/Eigen" "nlohmann=/usr/include/nlohmann" "CLI=/usr/include/CLI"
             "stb=/usr/include/stb" "spdlog=/usr/include/spdlog" "fmt=/usr/include/fmt")
  string(REPLACE "=" ";" kv ${pair})
  list(GET kv 0 name)
  list(GET kv 1 target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "the web build needs ${target} (scripts/install-deps.sh web)")
  endif()
  file(CREATE_LINK ${target} ${S4D_WEB_INCLUDE}/${name} SYMBOLIC)
endforeach()

function(s4d_web_headers target)
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${S4D_WEB_INCLUDE})
endfunction()
s4d_web_headers(Eigen3::Eigen)
s4d_web_headers(nlohmann_json::nlohmann_json)
s4d_web_headers(CLI11::CLI11)
s4d_web_headers(spdlog::spdlog)
set_property(TARGET spdlog::spdlog PROPERTY INTERFACE_COMPILE_DEFINITIONS SPDLOG_HEADER_ONLY FMT_HEADER_ONLY)
# GL, EGL and threads come with emscripten's own headers and JS libraries: nothing to link.
add_library(OpenGL::OpenGL INTERFACE IMPORTED GLOBAL)
add_library(OpenGL::EGL INTERFACE IMPORTED GLOBAL)
add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)
set(STB_INCLUDE_DIR ${S4D_WEB_INCLUDE})

# Exceptions are off in emscripten unless asked for; CLI11, nlohmann-json and our errors need them.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# Dear ImGui from its source package (the same version as libimgui-dev's headers natively).
set(S4D_IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui's sources (Debian's imgui source package, unpacked)")
if(NOT EXISTS ${S4D_IMGUI_SOURCE_DIR}/imgui.cpp)
  message(FATAL_ERROR "S4D_IMGUI_SOURCE_DIR ('${S4D_IMGUI_SOURCE_DIR}') has no imgui.cpp: "
                      "scripts/build-web.sh fetches Debian's imgui source package and sets it")
endif()
set(d ${S4D_IMGUI_SOURCE_DIR})
add_library(s4d_imgui_backends STATIC
  ${d}/imgui.cpp ${d}/imgui_draw.cpp ${d}/imgui_tables.cpp ${d}/imgui_widgets.cpp ${d}/imgui_demo.cpp
  ${d}/backends/imgui_impl_glfw.cpp ${d}/backends/imgui_impl_opengl3.cpp)
target_include_directories(s4d_imgui_backends PUBLIC ${d} ${d}/backends)
# WebGL2 is OpenGL ES 3.0: the backend's ES 3 path and "#version 300 es" shaders.
target_compile_definitions(s4d_imgui_backends PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(s4d_imgui_backends PRIVATE -w)
target_link_options(s4d_imgui_backends INTERFACE -sUSE_GLFW=3 -sUSE_WEBGL2=1 -sFULL_ES3=1 -sMAX_WEBGL_VERSION=2
                    -sMIN_WEBGL_VERSION=2)

# WebGL2 is OpenGL ES 3.0: our GL code and GLFW's header take the ES 3 headers (render/gl.hpp).
add_compile_definitions(S4D_GLES=1 GLFW_INCLUDE_ES3)

# The page's executable: the data as a preloaded package in the page's memory, laid out as a
# checkout (S4D_DATA_DIR=/shadow4d, set by index.html), IDBFS for the autosave folder, and the
# runtime functions index.html uses.
function(s4d_web_page target)
  target_link_options(${target} PRIVATE
    -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=128MB -sFORCE_FILESYSTEM=1 -lidbfs.js
    -sEXPORTED_RUNTIME_METHODS=[FS,ENV,IDBFS,callMain,UTF8ToString,addRunDependency,removeRunDependency]
    -sEXPORTED_FUNCTIONS=[_main,_malloc,_free]
    "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/data/knots@/shadow4d/data/knots"
    "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/scenarios@/shadow4d/scenarios"
    "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/scenes@/shadow4d/scenes"
    "SHELL:--exclude-file *.md")
  set_target_properties(${target} PROPERTIES SUFFIX ".js")
endfunction()
