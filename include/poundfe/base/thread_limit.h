// The threads a run may use (`--threads N`), for the parts of the program
// that are also built without deal.II (the interpreter's module
// poundfe-opensees.so, CMakeLists.txt's POUNDFE_LEAN_SOURCES): the program
// sets it beside deal.II's MultithreadInfo thread limit, which sizes TBB's
// pool; 1 until it does.
#ifndef poundfe_base_thread_limit_h
#define poundfe_base_thread_limit_h

namespace poundfe
{
  /// The threads `--threads` allows (1 unless set).
  unsigned int
  thread_limit();

  /// Set by the program where it sets deal.II's thread limit.
  void
  set_thread_limit(unsigned int n_threads);
} // namespace poundfe

#endif
