// a library file must not declare a version
#version 450 core
float lib_value;
