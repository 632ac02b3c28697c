// deal.II's Assert, AssertDimension and AssertIndexRange for the files of
// the OpenSees interpreter's module poundfe-opensees.so (CMakeLists.txt,
// POUNDFE_LEAN_SOURCES), which links without deal.II: a file that includes
// any deal.II header references Trilinos's Teuchos (the static objects of
// its headers) even where it calls nothing of deal.II. A Debug build (deal.II's
// DEBUG) takes deal.II's own macros, with their checks and messages, and
// links deal.II; a Release build compiles them to nothing, as deal.II's
// own Release definitions do. A programming error that must be caught in a
// Release build throws std::logic_error instead of AssertThrow.
#ifndef poundfe_base_lean_assert_h
#define poundfe_base_lean_assert_h

#ifdef DEBUG
#  include <deal.II/base/exceptions.h>
#else
#  ifndef Assert
#    define Assert(cond, exc) \
      {}
#  endif
#  ifndef AssertDimension
#    define AssertDimension(dim1, dim2) \
      {}
#  endif
#  ifndef AssertIndexRange
#    define AssertIndexRange(index, range) \
      {}
#  endif
#endif

#endif
