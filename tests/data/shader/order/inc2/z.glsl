// z from include dir 2
