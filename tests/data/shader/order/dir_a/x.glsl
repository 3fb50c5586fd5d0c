// x from the includer's directory
