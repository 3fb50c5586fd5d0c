// z from include dir 1
