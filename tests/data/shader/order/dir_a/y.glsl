// y from the root's directory
