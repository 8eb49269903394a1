#include "test.h"
void suite_contacts(void) {}
