#include <cstdio>
int main() { std::puts("multidir: commands are being built"); return 0; }
