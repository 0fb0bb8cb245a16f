int TestGlobeNewtonIterations(int, char*[]) { return 0; }
