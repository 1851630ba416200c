// Every fsweep library also compiles this file, so a library folder whose sources are still
// being written configures and links (CMake rejects a static library without sources).
