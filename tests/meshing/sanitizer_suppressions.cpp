// LeakSanitizer suppressions for test_meshing (compiled to nothing unless -DMRSIM_SANITIZE=ON).
// gmsh 4.8 leaks inside its own library: classifySurfaces/createGeometry replace the input
// discrete surface without freeing it (discreteFace, its MVertex/MTriangle/MLine vectors) and
// the 2-D mesher keeps a few per-face buffers. Every reported leak has libgmsh frames only
// below operator new; mrsim owns none of these objects (it only calls the API), and they are
// bounded per meshing attempt. Only leaks allocated from libgmsh are suppressed.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() { return "leak:libgmsh.so\n"; }
#endif
