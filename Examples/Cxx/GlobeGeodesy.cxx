#include <cstdio>
int main(){std::printf("Olympus Mons\n");return 0;}
