/* Bodies of round and compound shapes in a world, against analytic
   answers. */
#include "test.h"

void suite_shape_world(void) {}
