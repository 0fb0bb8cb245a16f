int TestGlobeTriaxialEllipsoid(int, char*[]) { return 0; }
