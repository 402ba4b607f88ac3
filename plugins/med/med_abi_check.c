/* Build-time check of the MED ABI that plugins/med/parasol_med_plugin.f90 assumes:
 * the sizes of med_int, med_idt, med_float and the values of the med.h constants it
 * passes to MED. A Debian MED built differently (64-bit med_int, another release with
 * renumbered enums) stops the build here instead of corrupting memory at run time. */
#include <med.h>

_Static_assert(sizeof(med_int) == 4, "parasol's MED plug-in binds med_int as int32");
_Static_assert(sizeof(med_idt) == 8, "parasol's MED plug-in binds med_idt as int64");
_Static_assert(sizeof(med_float) == 8, "med_float is a double");
_Static_assert(sizeof(med_bool) == 4 && sizeof(med_access_mode) == 4, "enums are int");
_Static_assert(MED_ACC_RDONLY == 0 && MED_ACC_RDWR == 1 && MED_ACC_CREAT == 3, "access");
_Static_assert(MED_CELL == 0 && MED_NODE == 3 && MED_NODE_ELEMENT == 4, "entity types");
_Static_assert(MED_COORDINATE == 0 && MED_CONNECTIVITY == 1 && MED_NAME == 2
               && MED_FAMILY_NUMBER == 4, "data types");
_Static_assert(MED_NODAL == 0 && MED_DESCENDING == 1 && MED_NO_CMODE == -1, "cmode");
_Static_assert(MED_FULL_INTERLACE == 0 && MED_COMPACT_STMODE == 2, "storage");
_Static_assert(MED_UNSTRUCTURED_MESH == 0 && MED_SORT_DTIT == 0 && MED_CARTESIAN == 0, "mesh");
_Static_assert(MED_FLOAT64 == 6 && MED_ALL_CONSTITUENT == 0, "field");
_Static_assert(MED_NONE == 0 && MED_GEO_ALL == -1 && MED_NO_DT == -1 && MED_NO_IT == -1,
               "steps");
_Static_assert(MED_NAME_SIZE == 64 && MED_SNAME_SIZE == 16 && MED_LNAME_SIZE == 80
               && MED_COMMENT_SIZE == 200, "string sizes");
_Static_assert(MED_POINT1 == 1 && MED_SEG2 == 102 && MED_TRIA3 == 203 && MED_QUAD4 == 204,
               "cell types");
_Static_assert(MED_SEG3 == 103 && MED_TRIA6 == 206 && MED_QUAD8 == 208 && MED_QUAD9 == 209,
               "quadratic cell types");

/* Not called: a translation unit needs one definition. */
int parasol_med_abi_checked(void) { return 1; }
