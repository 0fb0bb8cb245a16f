int TestGlobeGeodeticTransform(int, char*[]) { return 0; }
