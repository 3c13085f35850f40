// The object that carries a test folder's precompiled headers (tests/CMakeLists.txt); it holds
// no code of its own.
