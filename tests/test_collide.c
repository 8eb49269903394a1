#include "test.h"
void suite_collide(void) {}
