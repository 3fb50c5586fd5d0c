#pragma once
float once_lib() { return 1.0; }
