// PETSc error codes as exceptions: every PETSc call in runtime/petsc goes through check().
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace pd {

inline void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw std::runtime_error(std::string("PETSc: ") + what +
                           " failed: " + (text ? text : "error " + std::to_string(code)));
}

}  // namespace pd
