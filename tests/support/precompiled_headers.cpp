// The one source of tritri_test_pch (tests/CMakeLists.txt): the target exists to build the
// precompiled header that every test reuses; it defines nothing itself.
