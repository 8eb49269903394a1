/* Exact mass properties of the round shapes: circles, capsules and
   rounded polygons. */
#include "test.h"

void suite_shape_mass(void) {}
