# The layer order, lowest first: the ONE list every layer check reads.
#   - tests/architecture/check_layers.py (a CTest test) gets it on its command line and
#     fails when a file of engine/LAYER, cli/ or editor/ includes <sherpa/HIGHER/...>;
#   - sherpa_check_layer_links() (end of the root CMakeLists.txt) fails the configure
#     when a layer library or a test executable links a layer above its own, or a
#     test has no layer LABEL.
# A layer may use itself and every layer before it. Names joined by a comma are peers
# of one level that may not use each other (the CLI and the editor).
# `render` (the passes layer of issue #13) is listed before it exists: a missing
# layer is skipped, so adding engine/render needs no change here.
set(SHERPA_LAYERS core scene texture gpu render lab "cli,editor")

# The CMake target that is a layer: engine/LAYER builds sherpa_LAYER; the CLI and the
# editor are named after what they build.
function(sherpa_layer_target layer out)
  if(layer STREQUAL "cli")
    set(${out} sherpa-cli PARENT_SCOPE)
  elseif(layer STREQUAL "editor")
    set(${out} sherpa_editor_lib PARENT_SCOPE)
  else()
    set(${out} sherpa_${layer} PARENT_SCOPE)
  endif()
endfunction()

# Position of `layer` in SHERPA_LAYERS (peers share one), -1 when it is no layer.
function(sherpa_layer_rank layer out)
  set(rank 0)
  foreach(level ${SHERPA_LAYERS})
    string(REPLACE "," ";" peers "${level}")
    if(layer IN_LIST peers)
      set(${out} ${rank} PARENT_SCOPE)
      return()
    endif()
    math(EXPR rank "${rank} + 1")
  endforeach()
  set(${out} -1 PARENT_SCOPE)
endfunction()

# What every test's environment adds (CTest ENVIRONMENT_MODIFICATION, which leaves the
# tests' own ENVIRONMENT alone): one Mesa shader cache for every test, whatever
# XDG_CACHE_HOME a test or suite points elsewhere (the editor suites isolate theirs).
# lavapipe's LLVM compiles of the renderer's pipelines are much of a cold test run;
# with a cache per kind of test each pipeline was compiled once per cache.
set(SHERPA_TEST_ENVIRONMENT "MESA_SHADER_CACHE_DIR=set:${CMAKE_BINARY_DIR}/test-xdg-cache")

# Gives the tests of the calling directory SHERPA_TEST_ENVIRONMENT (deferred to the end
# of the directory, like sherpa_check_test_labels; discovered GoogleTest cases get it
# through sherpa_layer_test).
function(sherpa_set_test_environment)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test ${tests})
    set_property(TEST ${test} APPEND PROPERTY ENVIRONMENT_MODIFICATION ${SHERPA_TEST_ENVIRONMENT})
  endforeach()
endfunction()

# Registers test executable `target` as a test of `layer`: its link line is checked by
# sherpa_check_layer_links(), and every test of its directory must have a layer label. GoogleTest executables pass GTEST [PROPERTIES ...] to
# have their cases discovered with the layer as CTest LABEL (plus their properties);
# other tests set LABELS themselves with set_tests_properties.
function(sherpa_layer_test target layer)
  cmake_parse_arguments(arg "GTEST" "" "PROPERTIES" ${ARGN})
  sherpa_layer_rank(${layer} rank)
  if(rank LESS 0)
    message(FATAL_ERROR "sherpa_layer_test(${target}): '${layer}' is not in SHERPA_LAYERS")
  endif()
  set_property(GLOBAL APPEND PROPERTY SHERPA_LAYER_TESTS "${target}=${layer}")
  get_property(deferred DIRECTORY PROPERTY SHERPA_TEST_LABELS_CHECKED)
  if(NOT deferred)
    set_property(DIRECTORY PROPERTY SHERPA_TEST_LABELS_CHECKED TRUE)
    cmake_language(DEFER CALL sherpa_check_test_labels)
    cmake_language(DEFER CALL sherpa_set_test_environment)
  endif()
  if(arg_GTEST)
    gtest_discover_tests(${target} DISCOVERY_MODE PRE_TEST
                         PROPERTIES LABELS ${layer} ${arg_PROPERTIES}
                         ENVIRONMENT_MODIFICATION "${SHERPA_TEST_ENVIRONMENT}")
  endif()
endfunction()

# Collects into `out` the layers that `target` reaches through its link libraries
# (layer targets stop the walk: their own links are checked on their own) and through
# a build dependency on a layer's executable (tests that run sherpa-cli use the CLI).
function(sherpa_layers_used target out)
  set(found)
  set(todo ${target})
  set(seen)
  while(todo)
    list(POP_FRONT todo t)
    if(t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(libs ${t} LINK_LIBRARIES)
    get_target_property(ilibs ${t} INTERFACE_LINK_LIBRARIES)
    get_target_property(deps ${t} MANUALLY_ADDED_DEPENDENCIES)
    foreach(lib IN LISTS libs ilibs deps)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
      if(NOT TARGET "${lib}")
        continue()
      endif()
      get_target_property(imported ${lib} IMPORTED)
      if(imported)
        continue()
      endif()
      set(layer_of_lib "")
      foreach(level ${SHERPA_LAYERS})
        string(REPLACE "," ";" peers "${level}")
        foreach(layer ${peers})
          sherpa_layer_target(${layer} layer_target)
          if(lib STREQUAL layer_target AND NOT lib STREQUAL t)
            set(layer_of_lib ${layer})
          endif()
        endforeach()
      endforeach()
      if(layer_of_lib)
        list(APPEND found ${layer_of_lib})
      elseif(NOT lib STREQUAL t)
        list(APPEND todo ${lib}) # a helper library: what it links counts
      endif()
    endforeach()
  endwhile()
  list(REMOVE_DUPLICATES found)
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# `user` (of layer `layer`) may use `used` when it is the same layer or a lower level.
function(sherpa_check_uses user layer used_layers)
  sherpa_layer_rank(${layer} rank)
  foreach(used ${used_layers})
    sherpa_layer_rank(${used} used_rank)
    if(NOT used STREQUAL layer AND used_rank GREATER_EQUAL rank)
      message(FATAL_ERROR "layer violation: ${user} (layer ${layer}) uses layer ${used}; "
              "the order is ${SHERPA_LAYERS} (cmake/SherpaLayers.cmake). Move the test or "
              "the code to the layer it needs, or register the test with its real layer.")
    endif()
  endforeach()
endfunction()

# Every add_test() test of the current directory carries a layer (or `repo`, for checks
# of the whole tree) among its LABELS. Deferred to the end of each directory that
# registers a test executable (get_test_property sees only the current directory's
# tests); GoogleTest cases get their label from sherpa_layer_test(... GTEST).
function(sherpa_check_test_labels)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test ${tests})
    get_test_property(${test} LABELS labels)
    set(ok FALSE)
    foreach(label ${labels})
      sherpa_layer_rank(${label} rank)
      if(rank GREATER_EQUAL 0 OR label STREQUAL "repo")
        set(ok TRUE)
      endif()
    endforeach()
    if(NOT ok)
      message(FATAL_ERROR "test ${test} has no layer LABEL (one of ${SHERPA_LAYERS} or "
              "repo); set it with set_tests_properties(${test} PROPERTIES LABELS LAYER)")
    endif()
  endforeach()
endfunction()

# Checks every layer library that exists and every registered test executable.
function(sherpa_check_layer_links)
  foreach(level ${SHERPA_LAYERS})
    string(REPLACE "," ";" peers "${level}")
    foreach(layer ${peers})
      sherpa_layer_target(${layer} t)
      if(TARGET ${t})
        sherpa_layers_used(${t} used)
        sherpa_check_uses(${t} ${layer} "${used}")
      endif()
    endforeach()
  endforeach()
  get_property(tests GLOBAL PROPERTY SHERPA_LAYER_TESTS)
  foreach(entry ${tests})
    string(REPLACE "=" ";" pair ${entry})
    list(GET pair 0 t)
    list(GET pair 1 layer)
    sherpa_layers_used(${t} used)
    sherpa_check_uses(${t} ${layer} "${used}")
  endforeach()
endfunction()
