/* Manifolds between the round shapes and polygons. */
#include "test.h"

void suite_shape_collide(void) {}
