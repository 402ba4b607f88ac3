/* A stand-in for libparasol_med.so of another version (tests/med, case missing-plugin):
 * parasol must refuse it with a located message instead of calling its entry points. */
int parasol_med_abi_version(void) { return 99; }
