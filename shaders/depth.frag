#version 330 core
// Depth is written by the fixed pipeline; nothing to compute per fragment.

void main() {}
