// LeakSanitizer suppressions for the mrsim binary (compiled to nothing unless
// -DMRSIM_SANITIZE=ON), the same as the tests': a sanitizer build of `mrsim mesh` exited 1 after
// every successful meshing because of gmsh's own leaks (issue 18 defect 9).
// - gmsh 4.8: classifySurfaces/createGeometry replace the discrete input surface without
//   freeing it; bounded per meshing attempt, allocated from libgmsh only.
// - VTK 9.1's XML reader on a corrupt .vtu (the run then exits 2 anyway): ReadPieceData and
//   ReadArrayValues return early without freeing what they allocated.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libgmsh.so\n"
         "leak:vtkXMLUnstructuredGridReader::ReadPieceData\n"
         "leak:vtkXMLReader::ReadArrayValues\n";
}

// Debian's VTK is built without frame pointers: the slow unwinder lets the suppressions above
// see the VTK frames.
extern "C" const char* __asan_default_options() {
  return "fast_unwind_on_malloc=0:malloc_context_size=10";
}
#endif
