int TestGlobeEllipsoidBadInput(int, char*[]) { return 0; }
