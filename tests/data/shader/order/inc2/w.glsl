// w only in include dir 2
