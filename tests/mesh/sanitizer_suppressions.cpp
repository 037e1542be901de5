// LeakSanitizer suppressions for test_mesh (compiled to nothing unless -DMRSIM_SANITIZE=ON).
// VTK 9.1's XML reader leaks a few hundred bytes on its own error paths when a .vtu is
// corrupt: vtkXMLUnstructuredGridReader::ReadPieceData returns early without freeing the
// cell-types array it created, and vtkXMLReader::ReadArrayValues without freeing an array
// iterator. The robustness tests feed it corrupt files on purpose; the leaks are VTK's, not
// mrsim's, and bounded per failed read (which ends the program with exit code 2 anyway).
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:vtkXMLUnstructuredGridReader::ReadPieceData\n"
         "leak:vtkXMLReader::ReadArrayValues\n";
}

// Debian's VTK is built without frame pointers, so ASan's fast unwinder stops inside VTK and
// the suppressions above could not see the VTK reader frames; the slow unwinder, 10 frames
// deep, can (the sanitizer run takes ~13 s instead of ~7 s).
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0:malloc_context_size=10"; }
#endif
