// layout.cpp: struct sizes and offsets seen from C++.
#include "layout_check.h"
int main() { check_layouts(); return check_done("layout (C++)"); }
