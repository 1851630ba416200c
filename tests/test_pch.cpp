// The translation unit that builds the test executables' shared precompiled header
// (tests/CMakeLists.txt, fsweep_test_pch).
