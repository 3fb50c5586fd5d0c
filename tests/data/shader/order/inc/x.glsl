// x from include dir 1
