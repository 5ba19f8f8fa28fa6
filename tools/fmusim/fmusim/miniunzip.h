#pragma once

int miniunz_main(int argc, const char *argv[]);
