// LeakSanitizer suppressions for test_mesh (compiled to nothing unless -DMRSIM_SANITIZE=ON).
// VTK 9.1's XML reader leaks a few hundred bytes on its own error paths when a .vtu is
// corrupt: vtkXMLUnstructuredGridReader::ReadPieceData returns early without freeing the
// cell-types array it created, and vtkXMLReader::ReadArrayValues without freeing an array
// iterator; when an allocation fails (below), vtkXMLUnstructuredDataReader::ReadXMLData loses
// its per-piece array to the std::bad_alloc. The robustness tests feed it corrupt files on
// purpose; the leaks are VTK's, not mrsim's, and bounded per failed read (which ends the
// program with exit code 2 anyway).
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:vtkXMLUnstructuredGridReader::ReadPieceData\n"
         "leak:vtkXMLReader::ReadArrayValues\n"
         "leak:vtkXMLUnstructuredDataReader::ReadXMLData\n";
}

// Debian's VTK is built without frame pointers, so ASan's fast unwinder stops inside VTK and
// the suppressions above could not see the VTK reader frames; the slow unwinder, 10 frames
// deep, can (the sanitizer run takes ~13 s instead of ~7 s).
// allocator_may_return_null: a corrupt .vtu can make VTK ask for an impossible amount of
// memory (the connectivity array is sized by the last value of the offsets array, which only
// VTK decodes). A release build gets std::bad_alloc, which read_vtu turns into an InputError;
// ASan's default is to abort the program instead (allocation-size-too-big, found by the mesh
// fuzzer), so the sanitizer build would test another behaviour than the one shipped. Only
// malloc (VTK's data arrays) returns null with it: operator new still aborts under ASan, so a
// huge allocation in mrsim's own code (a std::vector sized by a lying count) is still reported.
extern "C" const char* __asan_default_options() {
  return "fast_unwind_on_malloc=0:malloc_context_size=10:allocator_may_return_null=1";
}
#endif
