// examples/step-2 on prm/step-2.prm: Tresca contact by the active set; face
// states and complementarity residuals rechecked, errors and rates.

// SOURCE_DIR, defined by deal.II's test macro, is tests/examples: the
// program then reads prm/step-2.prm of the source tree.
#define POLYFRAC_SOURCE_DIR SOURCE_DIR "/../.."
#include "../../examples/step-2/step-2.cc"
