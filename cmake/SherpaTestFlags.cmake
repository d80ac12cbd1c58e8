# Test code compiles at -O1 where the build type asks for optimization (-O2).
# Directory scope: the targets defined after include() in the including directory
# (test executables and their test-only helper libraries). The engine's libraries,
# the CLI and the editor keep the build type's flags. GCC takes the last -O given, and
# directory compile options come after CMAKE_CXX_FLAGS_<CONFIG>.
add_compile_options($<$<OR:$<CONFIG:RelWithDebInfo>,$<CONFIG:Release>>:-O1>)
