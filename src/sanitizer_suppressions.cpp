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
         "leak:vtkXMLReader::ReadArrayValues\n"
         "leak:vtkXMLUnstructuredDataReader::ReadXMLData\n";
}

// Debian's VTK is built without frame pointers: the slow unwinder lets the suppressions above
// see the VTK frames. allocator_may_return_null, as in tests/mesh: a corrupt .vtu can make VTK
// malloc an impossible size, which a release build reports as exit 2 (std::bad_alloc); ASan
// would abort instead (operator new in mrsim's own code still does).
extern "C" const char* __asan_default_options() {
  return "fast_unwind_on_malloc=0:malloc_context_size=10:allocator_may_return_null=1";
}
#endif
