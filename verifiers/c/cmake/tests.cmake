# Whether to build the project's own checks (PLCVEC_BUILD_TESTS: ON, OFF or AUTO), and their
# dependencies: a C++ compiler (the GoogleTest pattern, and a check that plcvec.h is C++), cJSON
# (the stdio adapter reads the protocol's JSON; Debian: libcjson-dev) and GoogleTest (Debian:
# libgtest-dev). ON requires all three, so that a check never goes missing unnoticed; AUTO takes
# them where this folder is the top-level project and all three are found. A macro, not a function:
# enable_language() and the imported targets of find_package() belong to the directory's scope.
macro(plcvec_tests_wanted out)
    string(TOUPPER "${PLCVEC_BUILD_TESTS}" _plcvec_wanted)
    set(${out} OFF)
    if(NOT _plcvec_wanted MATCHES "^(AUTO|ON|OFF|TRUE|FALSE|YES|NO|1|0)$")
        message(FATAL_ERROR "PLCVEC_BUILD_TESTS=${PLCVEC_BUILD_TESTS}: ON, OFF or AUTO")
    endif()
    if(_plcvec_wanted MATCHES "^(ON|TRUE|YES|1)$" OR (_plcvec_wanted STREQUAL "AUTO" AND PLCVEC_MAIN_PROJECT))
        include(CheckLanguage)
        check_language(CXX)
        set(_plcvec_missing "")
        if(NOT CMAKE_CXX_COMPILER)
            list(APPEND _plcvec_missing "a C++ compiler")
        endif()
        find_package(cJSON CONFIG QUIET)
        if(NOT cJSON_FOUND)
            list(APPEND _plcvec_missing "cJSON (Debian: apt-get install libcjson-dev)")
        endif()
        find_package(GTest QUIET)
        if(NOT GTest_FOUND)
            list(APPEND _plcvec_missing "GoogleTest (Debian: apt-get install libgtest-dev)")
        endif()
        list(JOIN _plcvec_missing ", " _plcvec_missing_text)
        if(NOT _plcvec_missing)
            enable_language(CXX)
            set(${out} ON)
        elseif(_plcvec_wanted STREQUAL "AUTO")
            message(STATUS "plcvec: building the library alone; its tests need ${_plcvec_missing_text} "
                           "(then -DPLCVEC_BUILD_TESTS=ON)")
        else()
            message(FATAL_ERROR "PLCVEC_BUILD_TESTS=${PLCVEC_BUILD_TESTS}: the tests and the stdio adapter need "
                                "${_plcvec_missing_text}; -DPLCVEC_BUILD_TESTS=OFF builds the library alone")
        endif()
    endif()
endmacro()
