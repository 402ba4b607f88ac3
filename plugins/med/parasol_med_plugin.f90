!> libparasol_med.so: parasol's plug-in for MED files (LIRE_MAILLAGE and IMPR_RESU with
!> FORMAT='MED'). It is the only code linked against Debian's MED C library (libmedC, which
!> pulls HDF5 and OpenMPI: ~47 shared libraries, ~10 ms per process start), and parasol opens
!> it with dlopen the first time a deck reads or writes MED (src/mesh/med_file.f90), so decks
!> without MED keep parasol's start-up.
!>
!> Each entry point is a thin bind(c) wrapper of one MED call (MED-fichier 4.1 C API,
!> med.h) with the conventions:
!>  - the result is an integer(c_int): 0 (or a count >= 0) on success, MED's negative error
!>    code on failure; PLUGIN_BAD_SIZE when a buffer given by the caller is too small;
!>  - strings in are NUL-terminated; strings out are written into the caller's buffers, whose
!>    sizes the entry point states (MED fixes them: names 64+1, entity names 16 per entity,
!>    group names 80 per group, component names 16 per component, plus the NUL);
!>  - arrays are interlaced (MED_FULL_INTERLACE): coordinates (spacedim, n), connectivity
!>    (nodes per cell, n), field values (components, n);
!>  - MED prints its own diagnostics on stderr whatever the caller wants (and HDF5 its error
!>    stacks): every call runs with file descriptor 2 sent to /dev/null, so that parasol
!>    reports one located message of its own instead.
!> The MED constants used below are those of med.h; med_abi_check.c verifies them, and the
!> sizes of med_int and med_idt, when the plug-in is built.
module parasol_med_plugin
    use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_char, c_ptr, &
        c_null_ptr, c_null_char, c_associated
    implicit none
    private

    !> Version of the entry points below; parasol refuses a plug-in of another version.
    integer(c_int), parameter :: ABI_VERSION = 2
    !> Returned when a caller's buffer is smaller than what the file holds.
    integer(c_int), parameter :: PLUGIN_BAD_SIZE = -900001
    !> Returned for an argument out of its documented range.
    integer(c_int), parameter :: PLUGIN_BAD_ARGUMENT = -900002

    ! med.h (MED-fichier 4.1): med_access_mode, med_entity_type, med_data_type,
    ! med_connectivity_mode, med_switch_mode, med_storage_mode, med_mesh_type, ...
    integer(c_int), parameter :: MED_ACC_RDONLY = 0, MED_ACC_RDWR = 1, MED_ACC_CREAT = 3
    integer(c_int), parameter :: MED_CELL = 0, MED_NODE = 3, MED_NODE_ELEMENT = 4
    integer(c_int), parameter :: MED_COORDINATE = 0, MED_CONNECTIVITY = 1, MED_NAME = 2, &
        MED_FAMILY_NUMBER = 4
    integer(c_int), parameter :: MED_NODAL = 0, MED_DESCENDING = 1, MED_NO_CMODE = -1
    integer(c_int), parameter :: MED_FULL_INTERLACE = 0, MED_COMPACT_STMODE = 2
    integer(c_int), parameter :: MED_UNSTRUCTURED_MESH = 0, MED_SORT_DTIT = 0, &
        MED_CARTESIAN = 0
    integer(c_int), parameter :: MED_FLOAT64 = 6, MED_ALL_CONSTITUENT = 0
    integer(c_int), parameter :: MED_NONE = 0, MED_GEO_ALL = -1
    integer(c_int), parameter :: MED_NO_DT = -1, MED_NO_IT = -1
    integer, parameter :: MED_NAME_SIZE = 64, MED_SNAME_SIZE = 16, MED_LNAME_SIZE = 80, &
        MED_COMMENT_SIZE = 200

    !> What parasol_med_count counts.
    integer(c_int), parameter :: COUNT_NODES = 1, COUNT_NODE_NAMES = 2, &
        COUNT_NODE_FAMILIES = 3, COUNT_CELLS = 4, COUNT_CELL_NAMES = 5, &
        COUNT_CELL_FAMILIES = 6, COUNT_NODAL_TYPES = 7, COUNT_DESCENDING_CELLS = 8
    !> Entity kinds of the name and family entry points.
    integer(c_int), parameter :: ENTITY_NODES = 1, ENTITY_CELLS = 2

    !> stderr while a MED call runs (see quiet_begin).
    integer(c_int), save :: saved_stderr = -1

    interface
        ! ---- MED-fichier (med.h) ----
        function MEDlibraryNumVersion(major, minor, release) result(rc) &
            bind(c, name='MEDlibraryNumVersion')
            import :: c_int
            integer(c_int), intent(out) :: major, minor, release
            integer(c_int) :: rc
        end function MEDlibraryNumVersion
        function MEDfileCompatibility(filename, hdfok, medok) result(rc) &
            bind(c, name='MEDfileCompatibility')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: filename(*)
            integer(c_int), intent(out) :: hdfok, medok
            integer(c_int) :: rc
        end function MEDfileCompatibility
        function MEDfileOpen(filename, mode) result(fid) bind(c, name='MEDfileOpen')
            import :: c_int, c_int64_t, c_char
            character(kind=c_char), intent(in) :: filename(*)
            integer(c_int), value :: mode
            integer(c_int64_t) :: fid
        end function MEDfileOpen
        function MEDfileNumVersionRd(fid, major, minor, release) result(rc) &
            bind(c, name='MEDfileNumVersionRd')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int), intent(out) :: major, minor, release
            integer(c_int) :: rc
        end function MEDfileNumVersionRd
        function MEDfileClose(fid) result(rc) bind(c, name='MEDfileClose')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: rc
        end function MEDfileClose
        function MEDnMesh(fid) result(n) bind(c, name='MEDnMesh')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: n
        end function MEDnMesh
        function MEDmeshnAxis(fid, meshit) result(n) bind(c, name='MEDmeshnAxis')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int), value :: meshit
            integer(c_int) :: n
        end function MEDmeshnAxis
        function MEDmeshInfo(fid, meshit, meshname, spacedim, meshdim, meshtype, &
                             description, dtunit, sortingtype, nstep, axistype, axisname, &
                             axisunit) result(rc) bind(c, name='MEDmeshInfo')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: meshit
            character(kind=c_char), intent(out) :: meshname(*), description(*), dtunit(*), &
                axisname(*), axisunit(*)
            integer(c_int), intent(out) :: spacedim, meshdim, meshtype, sortingtype, nstep, &
                axistype
            integer(c_int) :: rc
        end function MEDmeshInfo
        function MEDmeshComputationStepInfo(fid, meshname, csit, numdt, numit, dt) &
            result(rc) bind(c, name='MEDmeshComputationStepInfo')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: csit
            integer(c_int), intent(out) :: numdt, numit
            real(c_double), intent(out) :: dt
            integer(c_int) :: rc
        end function MEDmeshComputationStepInfo
        function MEDmeshnEntity(fid, meshname, numdt, numit, entitype, geotype, datatype, &
                                cmode, changement, transformation) result(n) &
            bind(c, name='MEDmeshnEntity')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, datatype, cmode
            integer(c_int), intent(out) :: changement, transformation
            integer(c_int) :: n
        end function MEDmeshnEntity
        function MEDmeshEntityInfo(fid, meshname, numdt, numit, entitype, geotypeit, &
                                   geotypename, geotype) result(rc) &
            bind(c, name='MEDmeshEntityInfo')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotypeit
            character(kind=c_char), intent(out) :: geotypename(*)
            integer(c_int), intent(out) :: geotype
            integer(c_int) :: rc
        end function MEDmeshEntityInfo
        function MEDmeshNodeCoordinateRd(fid, meshname, numdt, numit, switchmode, &
                                         coordinates) result(rc) &
            bind(c, name='MEDmeshNodeCoordinateRd')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, switchmode
            real(c_double), intent(out) :: coordinates(*)
            integer(c_int) :: rc
        end function MEDmeshNodeCoordinateRd
        function MEDmeshElementConnectivityRd(fid, meshname, numdt, numit, entitype, &
                                              geotype, cmode, switchmode, connectivity) &
            result(rc) bind(c, name='MEDmeshElementConnectivityRd')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, cmode, switchmode
            integer(c_int), intent(out) :: connectivity(*)
            integer(c_int) :: rc
        end function MEDmeshElementConnectivityRd
        function MEDmeshEntityNameRd(fid, meshname, numdt, numit, entitype, geotype, &
                                     names) result(rc) bind(c, name='MEDmeshEntityNameRd')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype
            character(kind=c_char), intent(out) :: names(*)
            integer(c_int) :: rc
        end function MEDmeshEntityNameRd
        function MEDmeshEntityFamilyNumberRd(fid, meshname, numdt, numit, entitype, &
                                             geotype, numbers) result(rc) &
            bind(c, name='MEDmeshEntityFamilyNumberRd')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype
            integer(c_int), intent(out) :: numbers(*)
            integer(c_int) :: rc
        end function MEDmeshEntityFamilyNumberRd
        function MEDnFamily(fid, meshname) result(n) bind(c, name='MEDnFamily')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int) :: n
        end function MEDnFamily
        function MEDnFamilyGroup(fid, meshname, famit) result(n) bind(c, name='MEDnFamilyGroup')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: famit
            integer(c_int) :: n
        end function MEDnFamilyGroup
        function MEDfamilyInfo(fid, meshname, famit, familyname, familynumber, groupname) &
            result(rc) bind(c, name='MEDfamilyInfo')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: famit
            character(kind=c_char), intent(out) :: familyname(*), groupname(*)
            integer(c_int), intent(out) :: familynumber
            integer(c_int) :: rc
        end function MEDfamilyInfo
        function MEDmeshCr(fid, meshname, spacedim, meshdim, meshtype, description, dtunit, &
                           sortingtype, axistype, axisname, axisunit) result(rc) &
            bind(c, name='MEDmeshCr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*), description(*), dtunit(*), &
                axisname(*), axisunit(*)
            integer(c_int), value :: spacedim, meshdim, meshtype, sortingtype, axistype
            integer(c_int) :: rc
        end function MEDmeshCr
        function MEDmeshNodeCoordinateWr(fid, meshname, numdt, numit, dt, switchmode, &
                                         nentity, coordinates) result(rc) &
            bind(c, name='MEDmeshNodeCoordinateWr')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, switchmode, nentity
            real(c_double), value :: dt
            real(c_double), intent(in) :: coordinates(*)
            integer(c_int) :: rc
        end function MEDmeshNodeCoordinateWr
        function MEDmeshElementConnectivityWr(fid, meshname, numdt, numit, dt, entitype, &
                                              geotype, cmode, switchmode, nentity, &
                                              connectivity) result(rc) &
            bind(c, name='MEDmeshElementConnectivityWr')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, cmode, switchmode, &
                nentity
            real(c_double), value :: dt
            integer(c_int), intent(in) :: connectivity(*)
            integer(c_int) :: rc
        end function MEDmeshElementConnectivityWr
        function MEDmeshEntityNameWr(fid, meshname, numdt, numit, entitype, geotype, &
                                     nentity, names) result(rc) &
            bind(c, name='MEDmeshEntityNameWr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*), names(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, nentity
            integer(c_int) :: rc
        end function MEDmeshEntityNameWr
        function MEDmeshEntityFamilyNumberWr(fid, meshname, numdt, numit, entitype, &
                                             geotype, nentity, numbers) result(rc) &
            bind(c, name='MEDmeshEntityFamilyNumberWr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, nentity
            integer(c_int), intent(in) :: numbers(*)
            integer(c_int) :: rc
        end function MEDmeshEntityFamilyNumberWr
        function MEDfamilyCr(fid, meshname, familyname, familynumber, ngroup, groupname) &
            result(rc) bind(c, name='MEDfamilyCr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: meshname(*), familyname(*), groupname(*)
            integer(c_int), value :: familynumber, ngroup
            integer(c_int) :: rc
        end function MEDfamilyCr
        function MEDnField(fid) result(n) bind(c, name='MEDnField')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: n
        end function MEDnField
        function MEDfieldnComponent(fid, ind) result(n) bind(c, name='MEDfieldnComponent')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int), value :: ind
            integer(c_int) :: n
        end function MEDfieldnComponent
        function MEDfieldInfo(fid, ind, fieldname, meshname, localmesh, fieldtype, &
                              componentname, componentunit, dtunit, ncstp) result(rc) &
            bind(c, name='MEDfieldInfo')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: ind
            character(kind=c_char), intent(out) :: fieldname(*), meshname(*), &
                componentname(*), componentunit(*), dtunit(*)
            integer(c_int), intent(out) :: localmesh, fieldtype, ncstp
            integer(c_int) :: rc
        end function MEDfieldInfo
        function MEDfieldCr(fid, fieldname, fieldtype, ncomponent, componentname, &
                            componentunit, dtunit, meshname) result(rc) &
            bind(c, name='MEDfieldCr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*), componentname(*), &
                componentunit(*), dtunit(*), meshname(*)
            integer(c_int), value :: fieldtype, ncomponent
            integer(c_int) :: rc
        end function MEDfieldCr
        function MEDnProfile(fid) result(n) bind(c, name='MEDnProfile')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: n
        end function MEDnProfile
        function MEDprofileWr(fid, profilename, profilesize, profilearray) result(rc) &
            bind(c, name='MEDprofileWr')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: profilename(*)
            integer(c_int), value :: profilesize
            integer(c_int), intent(in) :: profilearray(*)
            integer(c_int) :: rc
        end function MEDprofileWr
        function MEDfieldValueWithProfileWr(fid, fieldname, numdt, numit, dt, entitype, &
                                            geotype, storagemode, profilename, &
                                            localizationname, switchmode, componentselect, &
                                            nentity, values) result(rc) &
            bind(c, name='MEDfieldValueWithProfileWr')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*), profilename(*), &
                localizationname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, storagemode, &
                switchmode, componentselect, nentity
            real(c_double), value :: dt
            real(c_double), intent(in) :: values(*)
            integer(c_int) :: rc
        end function MEDfieldValueWithProfileWr
        ! ---- C library: silencing stderr around MED calls ----
        function MEDnLocalization(fid) result(n) bind(c, name='MEDnLocalization')
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: n
        end function MEDnLocalization
        function MEDlocalizationInfo(fid, it, locname, geotype, spacedim, nipoint, &
                                     geointerpname, sectionmeshname, nsectionmeshcell, &
                                     sectiongeotype) result(rc) &
            bind(c, name='MEDlocalizationInfo')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: it
            character(kind=c_char) :: locname(*), geointerpname(*), sectionmeshname(*)
            integer(c_int), intent(out) :: geotype, spacedim, nipoint, nsectionmeshcell, &
                sectiongeotype
            integer(c_int) :: rc
        end function MEDlocalizationInfo
        function MEDlocalizationWr(fid, locname, geotype, spacedim, elementcoordinate, &
                                   switchmode, nipoint, ipointcoordinate, weight, &
                                   geointerpname, ipointstructmeshname) result(rc) &
            bind(c, name='MEDlocalizationWr')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: locname(*), geointerpname(*), &
                ipointstructmeshname(*)
            integer(c_int), value :: geotype, spacedim, switchmode, nipoint
            real(c_double), intent(in) :: elementcoordinate(*), ipointcoordinate(*), weight(*)
            integer(c_int) :: rc
        end function MEDlocalizationWr
        function MEDfieldnComponentByName(fid, fieldname) result(n) &
            bind(c, name='MEDfieldnComponentByName')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*)
            integer(c_int) :: n
        end function MEDfieldnComponentByName
        function MEDfieldInfoByName(fid, fieldname, meshname, localmesh, fieldtype, &
                                    componentname, componentunit, dtunit, ncstp) result(rc) &
            bind(c, name='MEDfieldInfoByName')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*)
            character(kind=c_char) :: meshname(*), componentname(*), componentunit(*), &
                dtunit(*)
            integer(c_int), intent(out) :: localmesh, fieldtype, ncstp
            integer(c_int) :: rc
        end function MEDfieldInfoByName
        function MEDfieldComputingStepInfo(fid, fieldname, csit, numdt, numit, dt) &
            result(rc) bind(c, name='MEDfieldComputingStepInfo')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*)
            integer(c_int), value :: csit
            integer(c_int), intent(out) :: numdt, numit
            real(c_double), intent(out) :: dt
            integer(c_int) :: rc
        end function MEDfieldComputingStepInfo
        function MEDfieldnProfile(fid, fieldname, numdt, numit, entitype, geotype, &
                                  defaultprofilename, defaultlocalizationname) result(n) &
            bind(c, name='MEDfieldnProfile')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype
            character(kind=c_char) :: defaultprofilename(*), defaultlocalizationname(*)
            integer(c_int) :: n
        end function MEDfieldnProfile
        function MEDfieldnValueWithProfile(fid, fieldname, numdt, numit, entitype, geotype, &
                                           profileit, storagemode, profilename, profilesize, &
                                           localizationname, nintegrationpoint) result(n) &
            bind(c, name='MEDfieldnValueWithProfile')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, profileit, storagemode
            character(kind=c_char) :: profilename(*), localizationname(*)
            integer(c_int), intent(out) :: profilesize, nintegrationpoint
            integer(c_int) :: n
        end function MEDfieldnValueWithProfile
        function MEDfieldValueWithProfileRd(fid, fieldname, numdt, numit, entitype, geotype, &
                                            storagemode, profilename, switchmode, &
                                            componentselect, values) result(rc) &
            bind(c, name='MEDfieldValueWithProfileRd')
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: fieldname(*), profilename(*)
            integer(c_int), value :: numdt, numit, entitype, geotype, storagemode, &
                switchmode, componentselect
            real(c_double) :: values(*)
            integer(c_int) :: rc
        end function MEDfieldValueWithProfileRd
        function MEDprofileSizeByName(fid, profilename) result(n) &
            bind(c, name='MEDprofileSizeByName')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: profilename(*)
            integer(c_int) :: n
        end function MEDprofileSizeByName
        function MEDprofileRd(fid, profilename, profilearray) result(rc) &
            bind(c, name='MEDprofileRd')
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: profilename(*)
            integer(c_int) :: profilearray(*)
            integer(c_int) :: rc
        end function MEDprofileRd
        function c_dup(fd) result(rc) bind(c, name='dup')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_dup
        function c_dup2(fd, fd2) result(rc) bind(c, name='dup2')
            import :: c_int
            integer(c_int), value :: fd, fd2
            integer(c_int) :: rc
        end function c_dup2
        function c_close(fd) result(rc) bind(c, name='close')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_close
        function c_fopen(path, mode) result(stream) bind(c, name='fopen')
            import :: c_ptr, c_char
            character(kind=c_char), intent(in) :: path(*), mode(*)
            type(c_ptr) :: stream
        end function c_fopen
        function c_fileno(stream) result(fd) bind(c, name='fileno')
            import :: c_ptr, c_int
            type(c_ptr), value :: stream
            integer(c_int) :: fd
        end function c_fileno
        function c_fclose(stream) result(rc) bind(c, name='fclose')
            import :: c_ptr, c_int
            type(c_ptr), value :: stream
            integer(c_int) :: rc
        end function c_fclose
        function c_fflush(stream) result(rc) bind(c, name='fflush')
            import :: c_ptr, c_int
            type(c_ptr), value :: stream
            integer(c_int) :: rc
        end function c_fflush
    end interface

    public :: parasol_med_abi_version, parasol_med_library_version, &
        parasol_med_file_compatibility, parasol_med_open, parasol_med_file_version, &
        parasol_med_close, parasol_med_mesh_count, parasol_med_mesh_info, &
        parasol_med_mesh_step, parasol_med_count, parasol_med_cell_type, &
        parasol_med_read_coordinates, &
        parasol_med_read_connectivity, parasol_med_read_names, parasol_med_read_families, &
        parasol_med_family_count, parasol_med_family_group_count, parasol_med_family_info, &
        parasol_med_create_mesh, parasol_med_write_coordinates, &
        parasol_med_write_connectivity, parasol_med_write_names, &
        parasol_med_write_families, parasol_med_create_family, parasol_med_field_count, &
        parasol_med_field_component_count, parasol_med_field_info, &
        parasol_med_create_field, parasol_med_profile_count, parasol_med_write_profile, &
        parasol_med_write_field_values, parasol_med_localization_count, &
        parasol_med_localization_name, parasol_med_write_localization, &
        parasol_med_write_entity_values, parasol_med_field_step_count, &
        parasol_med_field_step_info, parasol_med_field_profile_count, &
        parasol_med_field_value_info, parasol_med_read_entity_values, &
        parasol_med_read_profile

contains

    !> ABI_VERSION, checked by parasol when it loads the plug-in.
    function parasol_med_abi_version() result(version) bind(c, name='parasol_med_abi_version')
        integer(c_int) :: version
        version = ABI_VERSION
    end function parasol_med_abi_version

    !> Version of the MED library the plug-in runs with (MEDlibraryNumVersion).
    function parasol_med_library_version(major, minor, release) result(rc) &
        bind(c, name='parasol_med_library_version')
        integer(c_int), intent(out) :: major, minor, release
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDlibraryNumVersion(major, minor, release)
        call quiet_end()
    end function parasol_med_library_version

    !> Whether `path` is an HDF5 file (hdf_ok = 1) and a MED file this library reads
    !> (med_ok = 1), without opening it (MEDfileCompatibility).
    function parasol_med_file_compatibility(path, hdf_ok, med_ok) result(rc) &
        bind(c, name='parasol_med_file_compatibility')
        character(kind=c_char), intent(in) :: path(*)
        integer(c_int), intent(out) :: hdf_ok, med_ok
        integer(c_int) :: rc
        hdf_ok = 0
        med_ok = 0
        call quiet_begin()
        rc = MEDfileCompatibility(path, hdf_ok, med_ok)
        call quiet_end()
    end function parasol_med_file_compatibility

    !> Opens `path`: mode 0 reads, 1 creates (replacing any file), 2 adds to an existing
    !> file (writing an object that exists replaces it: MED_ACC_RDWR, the mode Code_Aster's
    !> IMPR_RESU opens an existing file with).
    !>  fid : out, the MED file id (> 0) on success
    function parasol_med_open(path, mode, fid) result(rc) bind(c, name='parasol_med_open')
        character(kind=c_char), intent(in) :: path(*)
        integer(c_int), value :: mode
        integer(c_int64_t), intent(out) :: fid
        integer(c_int) :: rc, access
        fid = -1
        select case (mode)
        case (0)
            access = MED_ACC_RDONLY
        case (1)
            access = MED_ACC_CREAT
        case (2)
            access = MED_ACC_RDWR
        case default
            rc = PLUGIN_BAD_ARGUMENT
            return
        end select
        call quiet_begin()
        fid = MEDfileOpen(path, access)
        call quiet_end()
        rc = 0
        if (fid < 0) rc = int(min(-1_c_int64_t, fid), c_int)
    end function parasol_med_open

    !> MED version the file was written with (MEDfileNumVersionRd).
    function parasol_med_file_version(fid, major, minor, release) result(rc) &
        bind(c, name='parasol_med_file_version')
        integer(c_int64_t), value :: fid
        integer(c_int), intent(out) :: major, minor, release
        integer(c_int) :: rc
        major = -1
        minor = -1
        release = -1
        call quiet_begin()
        rc = MEDfileNumVersionRd(fid, major, minor, release)
        call quiet_end()
    end function parasol_med_file_version

    !> Closes the file (MEDfileClose); a file opened for writing is complete only then.
    function parasol_med_close(fid) result(rc) bind(c, name='parasol_med_close')
        integer(c_int64_t), value :: fid
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDfileClose(fid)
        call quiet_end()
    end function parasol_med_close

    !> Number of meshes in the file (MEDnMesh).
    function parasol_med_mesh_count(fid) result(n) bind(c, name='parasol_med_mesh_count')
        integer(c_int64_t), value :: fid
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnMesh(fid)
        call quiet_end()
    end function parasol_med_mesh_count

    !> Mesh number `it` (1-based): its name (buffer of 65 characters), space and mesh
    !> dimensions, structured = 1 for a structured grid, and its number of computation
    !> steps. The space dimension is read first (MEDmeshnAxis) and must be 1..3, since
    !> MEDmeshInfo writes 16 characters per axis into the axis buffers.
    function parasol_med_mesh_info(fid, it, name, spacedim, meshdim, structured, nstep) &
        result(rc) bind(c, name='parasol_med_mesh_info')
        integer(c_int64_t), value :: fid
        integer(c_int), value :: it
        character(kind=c_char), intent(out) :: name(MED_NAME_SIZE + 1)
        integer(c_int), intent(out) :: spacedim, meshdim, structured, nstep
        integer(c_int) :: rc, meshtype, sortingtype, axistype, naxis
        character(kind=c_char) :: description(MED_COMMENT_SIZE + 1), dtunit(MED_SNAME_SIZE + 1)
        character(kind=c_char) :: axisname(3 * MED_SNAME_SIZE + 1), &
            axisunit(3 * MED_SNAME_SIZE + 1)
        name = c_null_char
        spacedim = 0
        meshdim = 0
        structured = 0
        nstep = 0
        call quiet_begin()
        naxis = MEDmeshnAxis(fid, it)
        call quiet_end()
        if (naxis < 0) then
            rc = naxis
            return
        end if
        if (naxis < 1 .or. naxis > 3) then
            spacedim = naxis
            rc = PLUGIN_BAD_SIZE
            return
        end if
        call quiet_begin()
        rc = MEDmeshInfo(fid, it, name, spacedim, meshdim, meshtype, description, dtunit, &
                         sortingtype, nstep, axistype, axisname, axisunit)
        call quiet_end()
        if (meshtype /= MED_UNSTRUCTURED_MESH) structured = 1
    end function parasol_med_mesh_info

    !> Computation step number `it` (1-based) of mesh `mesh`: its (numdt, numit).
    function parasol_med_mesh_step(fid, mesh, it, numdt, numit) result(rc) &
        bind(c, name='parasol_med_mesh_step')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: it
        integer(c_int), intent(out) :: numdt, numit
        integer(c_int) :: rc
        real(c_double) :: dt
        numdt = MED_NO_DT
        numit = MED_NO_IT
        call quiet_begin()
        rc = MEDmeshComputationStepInfo(fid, mesh, it, numdt, numit, dt)
        call quiet_end()
    end function parasol_med_mesh_step

    !> A count of mesh `mesh` at step (numdt, numit) (MEDmeshnEntity); `what`: 1 nodes,
    !> 2 node names, 3 node family numbers, 4 cells of MED type `geotype` (nodal
    !> connectivity), 5 their names, 6 their family numbers, 7 cell types present (any
    !> connectivity), 8 cells of type `geotype` given by descending connectivity. 0 when
    !> absent.
    function parasol_med_count(fid, mesh, numdt, numit, what, geotype) result(n) &
        bind(c, name='parasol_med_count')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit, what, geotype
        integer(c_int) :: n, changed, transformed
        integer(c_int) :: entity, geo, datatype, cmode
        select case (what)
        case (COUNT_NODES, COUNT_NODE_NAMES, COUNT_NODE_FAMILIES)
            entity = MED_NODE
            geo = MED_NONE
            cmode = MED_NO_CMODE
            datatype = MED_COORDINATE
            if (what == COUNT_NODE_NAMES) datatype = MED_NAME
            if (what == COUNT_NODE_FAMILIES) datatype = MED_FAMILY_NUMBER
        case (COUNT_CELLS, COUNT_CELL_NAMES, COUNT_CELL_FAMILIES)
            entity = MED_CELL
            geo = geotype
            cmode = MED_NODAL
            datatype = MED_CONNECTIVITY
            if (what == COUNT_CELL_NAMES) datatype = MED_NAME
            if (what == COUNT_CELL_FAMILIES) datatype = MED_FAMILY_NUMBER
        case (COUNT_NODAL_TYPES)
            entity = MED_CELL
            geo = MED_GEO_ALL
            datatype = MED_CONNECTIVITY
            cmode = MED_NODAL
        case (COUNT_DESCENDING_CELLS)
            entity = MED_CELL
            geo = geotype
            datatype = MED_CONNECTIVITY
            cmode = MED_DESCENDING
        case default
            n = PLUGIN_BAD_ARGUMENT
            return
        end select
        call quiet_begin()
        n = MEDmeshnEntity(fid, mesh, numdt, numit, entity, geo, datatype, cmode, changed, &
                           transformed)
        call quiet_end()
    end function parasol_med_count

    !> MED type code of cell type number `it` (1-based iterator over the cell types present,
    !> counted by parasol_med_count with what = 7), MEDmeshEntityInfo.
    function parasol_med_cell_type(fid, mesh, numdt, numit, it, geotype) result(rc) &
        bind(c, name='parasol_med_cell_type')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit, it
        integer(c_int), intent(out) :: geotype
        integer(c_int) :: rc
        character(kind=c_char) :: name(MED_NAME_SIZE + 1)   ! MED writes up to 64 + NUL
        geotype = 0
        call quiet_begin()
        rc = MEDmeshEntityInfo(fid, mesh, numdt, numit, MED_CELL, it, name, geotype)
        call quiet_end()
    end function parasol_med_cell_type

    !> Node coordinates, interlaced: (spacedim, n) as counted by parasol_med_count.
    function parasol_med_read_coordinates(fid, mesh, numdt, numit, coordinates) result(rc) &
        bind(c, name='parasol_med_read_coordinates')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit
        real(c_double), intent(out) :: coordinates(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDmeshNodeCoordinateRd(fid, mesh, numdt, numit, MED_FULL_INTERLACE, coordinates)
        call quiet_end()
    end function parasol_med_read_coordinates

    !> Nodal connectivity of the cells of MED type `geotype`: (nodes per cell, n), node
    !> numbers 1-based in the order of the coordinates.
    function parasol_med_read_connectivity(fid, mesh, numdt, numit, geotype, connectivity) &
        result(rc) bind(c, name='parasol_med_read_connectivity')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit, geotype
        integer(c_int), intent(out) :: connectivity(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDmeshElementConnectivityRd(fid, mesh, numdt, numit, MED_CELL, geotype, &
                                          MED_NODAL, MED_FULL_INTERLACE, connectivity)
        call quiet_end()
    end function parasol_med_read_connectivity

    !> Names of the nodes (entity 1) or of the cells of type `geotype` (entity 2): 16
    !> characters each, blank-padded, plus a NUL (buffer of 16 n + 1).
    function parasol_med_read_names(fid, mesh, numdt, numit, entity, geotype, names) &
        result(rc) bind(c, name='parasol_med_read_names')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit, entity, geotype
        character(kind=c_char), intent(out) :: names(*)
        integer(c_int) :: rc
        if (entity /= ENTITY_NODES .and. entity /= ENTITY_CELLS) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        call quiet_begin()
        if (entity == ENTITY_NODES) then
            rc = MEDmeshEntityNameRd(fid, mesh, numdt, numit, MED_NODE, MED_NONE, names)
        else
            rc = MEDmeshEntityNameRd(fid, mesh, numdt, numit, MED_CELL, geotype, names)
        end if
        call quiet_end()
    end function parasol_med_read_names

    !> Family numbers of the nodes (entity 1) or of the cells of type `geotype` (entity 2).
    function parasol_med_read_families(fid, mesh, numdt, numit, entity, geotype, numbers) &
        result(rc) bind(c, name='parasol_med_read_families')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: numdt, numit, entity, geotype
        integer(c_int), intent(out) :: numbers(*)
        integer(c_int) :: rc
        if (entity /= ENTITY_NODES .and. entity /= ENTITY_CELLS) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        call quiet_begin()
        if (entity == ENTITY_NODES) then
            rc = MEDmeshEntityFamilyNumberRd(fid, mesh, numdt, numit, MED_NODE, MED_NONE, &
                                             numbers)
        else
            rc = MEDmeshEntityFamilyNumberRd(fid, mesh, numdt, numit, MED_CELL, geotype, &
                                             numbers)
        end if
        call quiet_end()
    end function parasol_med_read_families

    !> Number of families of mesh `mesh` (MEDnFamily).
    function parasol_med_family_count(fid, mesh) result(n) &
        bind(c, name='parasol_med_family_count')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnFamily(fid, mesh)
        call quiet_end()
    end function parasol_med_family_count

    !> Number of groups of family number `it` (1-based iterator, MEDnFamilyGroup).
    function parasol_med_family_group_count(fid, mesh, it) result(n) &
        bind(c, name='parasol_med_family_group_count')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: it
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnFamilyGroup(fid, mesh, it)
        call quiet_end()
    end function parasol_med_family_group_count

    !> Family `it` (1-based iterator): name (65 characters), number, and its group names
    !> (80 characters each plus a NUL, in a buffer for `capacity` groups). PLUGIN_BAD_SIZE
    !> when the family has more than `capacity` groups.
    function parasol_med_family_info(fid, mesh, it, capacity, name, number, groups) &
        result(rc) bind(c, name='parasol_med_family_info')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: it, capacity
        character(kind=c_char), intent(out) :: name(MED_NAME_SIZE + 1)
        integer(c_int), intent(out) :: number
        character(kind=c_char), intent(out) :: groups(*)
        integer(c_int) :: rc, n
        name = c_null_char
        number = 0
        call quiet_begin()
        n = MEDnFamilyGroup(fid, mesh, it)
        call quiet_end()
        if (n < 0) then
            rc = n
            return
        else if (n > capacity) then
            rc = PLUGIN_BAD_SIZE
            return
        end if
        call quiet_begin()
        rc = MEDfamilyInfo(fid, mesh, it, name, number, groups)
        call quiet_end()
    end function parasol_med_family_info

    !> Creates unstructured mesh `mesh` of dimension `spacedim` (2 or 3; mesh dimension =
    !> space dimension, Cartesian axes X, Y, Z of unknown unit, as Code_Aster writes them).
    function parasol_med_create_mesh(fid, mesh, spacedim, description) result(rc) &
        bind(c, name='parasol_med_create_mesh')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*), description(*)
        integer(c_int), value :: spacedim
        integer(c_int) :: rc
        character(len=3 * MED_SNAME_SIZE, kind=c_char) :: names, units
        if (spacedim < 1 .or. spacedim > 3) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        names = 'X' // repeat(' ', MED_SNAME_SIZE - 1) // 'Y' // repeat(' ', MED_SNAME_SIZE - 1) &
            // 'Z' // repeat(' ', MED_SNAME_SIZE - 1)
        units = repeat('INCONNU' // repeat(' ', MED_SNAME_SIZE - 7), 3)
        call quiet_begin()
        rc = MEDmeshCr(fid, mesh, spacedim, spacedim, MED_UNSTRUCTURED_MESH, description, &
                       '' // c_null_char, MED_SORT_DTIT, MED_CARTESIAN, &
                       names(1:MED_SNAME_SIZE * spacedim) // c_null_char, &
                       units(1:MED_SNAME_SIZE * spacedim) // c_null_char)
        call quiet_end()
    end function parasol_med_create_mesh

    !> Writes the n node coordinates (spacedim, n) of mesh `mesh` (no computation step).
    function parasol_med_write_coordinates(fid, mesh, n, coordinates) result(rc) &
        bind(c, name='parasol_med_write_coordinates')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: n
        real(c_double), intent(in) :: coordinates(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDmeshNodeCoordinateWr(fid, mesh, MED_NO_DT, MED_NO_IT, 0.0_c_double, &
                                     MED_FULL_INTERLACE, n, coordinates)
        call quiet_end()
    end function parasol_med_write_coordinates

    !> Writes n cells of MED type `geotype`, nodal connectivity (nodes per cell, n).
    function parasol_med_write_connectivity(fid, mesh, geotype, n, connectivity) &
        result(rc) bind(c, name='parasol_med_write_connectivity')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: geotype, n
        integer(c_int), intent(in) :: connectivity(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDmeshElementConnectivityWr(fid, mesh, MED_NO_DT, MED_NO_IT, 0.0_c_double, &
                                          MED_CELL, geotype, MED_NODAL, MED_FULL_INTERLACE, &
                                          n, connectivity)
        call quiet_end()
    end function parasol_med_write_connectivity

    !> Writes the names (16 characters each, blank-padded) of the n nodes (entity 1) or of
    !> the n cells of type `geotype` (entity 2).
    function parasol_med_write_names(fid, mesh, entity, geotype, n, names) result(rc) &
        bind(c, name='parasol_med_write_names')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*), names(*)
        integer(c_int), value :: entity, geotype, n
        integer(c_int) :: rc
        if (entity /= ENTITY_NODES .and. entity /= ENTITY_CELLS) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        call quiet_begin()
        if (entity == ENTITY_NODES) then
            rc = MEDmeshEntityNameWr(fid, mesh, MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, n, &
                                     names)
        else
            rc = MEDmeshEntityNameWr(fid, mesh, MED_NO_DT, MED_NO_IT, MED_CELL, geotype, n, &
                                     names)
        end if
        call quiet_end()
    end function parasol_med_write_names

    !> Writes the family numbers of the n nodes (entity 1) or cells of type `geotype` (2).
    function parasol_med_write_families(fid, mesh, entity, geotype, n, numbers) result(rc) &
        bind(c, name='parasol_med_write_families')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*)
        integer(c_int), value :: entity, geotype, n
        integer(c_int), intent(in) :: numbers(*)
        integer(c_int) :: rc
        if (entity /= ENTITY_NODES .and. entity /= ENTITY_CELLS) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        call quiet_begin()
        if (entity == ENTITY_NODES) then
            rc = MEDmeshEntityFamilyNumberWr(fid, mesh, MED_NO_DT, MED_NO_IT, MED_NODE, &
                                             MED_NONE, n, numbers)
        else
            rc = MEDmeshEntityFamilyNumberWr(fid, mesh, MED_NO_DT, MED_NO_IT, MED_CELL, &
                                             geotype, n, numbers)
        end if
        call quiet_end()
    end function parasol_med_write_families

    !> Creates family `name` (number > 0 for nodes, < 0 for cells, 0 for none) with
    !> `ngroups` group names of 80 characters each, blank-padded (MEDfamilyCr).
    function parasol_med_create_family(fid, mesh, name, number, ngroups, groups) result(rc) &
        bind(c, name='parasol_med_create_family')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: mesh(*), name(*), groups(*)
        integer(c_int), value :: number, ngroups
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDfamilyCr(fid, mesh, name, number, ngroups, groups)
        call quiet_end()
    end function parasol_med_create_family

    !> Number of fields in the file (MEDnField).
    function parasol_med_field_count(fid) result(n) bind(c, name='parasol_med_field_count')
        integer(c_int64_t), value :: fid
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnField(fid)
        call quiet_end()
    end function parasol_med_field_count

    !> Number of components of field `it` (1-based iterator, MEDfieldnComponent).
    function parasol_med_field_component_count(fid, it) result(n) &
        bind(c, name='parasol_med_field_component_count')
        integer(c_int64_t), value :: fid
        integer(c_int), value :: it
        integer(c_int) :: n
        call quiet_begin()
        n = MEDfieldnComponent(fid, it)
        call quiet_end()
    end function parasol_med_field_component_count

    !> Field `it` (1-based iterator): its name and mesh name (65 characters each) and its
    !> component names (16 characters each plus a NUL, in a buffer for `capacity`
    !> components). PLUGIN_BAD_SIZE when the field has more than `capacity` components.
    function parasol_med_field_info(fid, it, capacity, name, mesh, ncomponent, components) &
        result(rc) bind(c, name='parasol_med_field_info')
        integer(c_int64_t), value :: fid
        integer(c_int), value :: it, capacity
        character(kind=c_char), intent(out) :: name(MED_NAME_SIZE + 1), &
            mesh(MED_NAME_SIZE + 1), components(*)
        integer(c_int), intent(out) :: ncomponent
        integer(c_int) :: rc, localmesh, fieldtype, nstep
        character(kind=c_char), allocatable :: units(:)
        character(kind=c_char) :: dtunit(MED_SNAME_SIZE + 1)
        name = c_null_char
        mesh = c_null_char
        call quiet_begin()
        ncomponent = MEDfieldnComponent(fid, it)
        call quiet_end()
        if (ncomponent < 0) then
            rc = ncomponent
            return
        else if (ncomponent > capacity) then
            rc = PLUGIN_BAD_SIZE
            return
        end if
        allocate (units(MED_SNAME_SIZE * max(ncomponent, 1_c_int) + 1))
        call quiet_begin()
        rc = MEDfieldInfo(fid, it, name, mesh, localmesh, fieldtype, components, units, &
                          dtunit, nstep)
        call quiet_end()
    end function parasol_med_field_info

    !> Creates a float64 field `field` on mesh `mesh` with `ncomponent` components (names
    !> and units 16 characters each, blank-padded), time unit left blank (MEDfieldCr).
    function parasol_med_create_field(fid, field, mesh, ncomponent, components, units) &
        result(rc) bind(c, name='parasol_med_create_field')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*), mesh(*), components(*), units(*)
        integer(c_int), value :: ncomponent
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDfieldCr(fid, field, MED_FLOAT64, ncomponent, components, units, &
                        '' // c_null_char, mesh)
        call quiet_end()
    end function parasol_med_create_field

    !> Number of profiles in the file (MEDnProfile).
    function parasol_med_profile_count(fid) result(n) bind(c, name='parasol_med_profile_count')
        integer(c_int64_t), value :: fid
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnProfile(fid)
        call quiet_end()
    end function parasol_med_profile_count

    !> Writes profile `name`: the n entity numbers (1-based) a field is given on.
    function parasol_med_write_profile(fid, name, n, numbers) result(rc) &
        bind(c, name='parasol_med_write_profile')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: name(*)
        integer(c_int), value :: n
        integer(c_int), intent(in) :: numbers(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDprofileWr(fid, name, n, numbers)
        call quiet_end()
    end function parasol_med_write_profile

    !> Writes the values of node field `field` at computation step (numdt, numit), time
    !> `dt`: (components, n) interlaced, on the nodes of profile `profile` ('' = every node
    !> of the mesh, in order; else n = the profile's size, compact storage).
    function parasol_med_write_field_values(fid, field, numdt, numit, dt, n, profile, &
                                            values) result(rc) &
        bind(c, name='parasol_med_write_field_values')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*), profile(*)
        integer(c_int), value :: numdt, numit, n
        real(c_double), value :: dt
        real(c_double), intent(in) :: values(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDfieldValueWithProfileWr(fid, field, numdt, numit, dt, MED_NODE, MED_NONE, &
                                        MED_COMPACT_STMODE, profile, '' // c_null_char, &
                                        MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, n, values)
        call quiet_end()
    end function parasol_med_write_field_values

    !> Number of Gauss-point localisations in the file (MEDnLocalization).
    function parasol_med_localization_count(fid) result(n) &
        bind(c, name='parasol_med_localization_count')
        integer(c_int64_t), value :: fid
        integer(c_int) :: n
        call quiet_begin()
        n = MEDnLocalization(fid)
        call quiet_end()
    end function parasol_med_localization_count

    !> Name of localisation `it` (1-based; name: 64 + NUL) (MEDlocalizationInfo).
    function parasol_med_localization_name(fid, it, name) result(rc) &
        bind(c, name='parasol_med_localization_name')
        integer(c_int64_t), value :: fid
        integer(c_int), value :: it
        character(kind=c_char) :: name(MED_NAME_SIZE + 1)
        integer(c_int) :: rc, geotype, spacedim, nipoint, nsection, sectiontype
        character(kind=c_char) :: interp(MED_NAME_SIZE + 1), section(MED_NAME_SIZE + 1)
        name = c_null_char
        call quiet_begin()
        rc = MEDlocalizationInfo(fid, it, name, geotype, spacedim, nipoint, interp, &
                                 section, nsection, sectiontype)
        call quiet_end()
    end function parasol_med_localization_name

    !> Writes localisation `name` of `npoints` integration points on reference cells of MED
    !> type `geotype` in dimension `dim`: the reference element's nodes refcoo(dim, nodes),
    !> the points gscoo(dim, npoints) and their weights, interlaced, without interpolation
    !> nor structural-element mesh (MEDlocalizationWr).
    function parasol_med_write_localization(fid, name, geotype, dim, refcoo, npoints, &
                                            gscoo, weights) result(rc) &
        bind(c, name='parasol_med_write_localization')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: name(*)
        integer(c_int), value :: geotype, dim, npoints
        real(c_double), intent(in) :: refcoo(*), gscoo(*), weights(*)
        integer(c_int) :: rc
        call quiet_begin()
        rc = MEDlocalizationWr(fid, name, geotype, dim, refcoo, MED_FULL_INTERLACE, npoints, &
                               gscoo, weights, '' // c_null_char, '' // c_null_char)
        call quiet_end()
    end function parasol_med_write_localization

    !> Writes the values of field `field` at step (numdt, numit), time dt, on n cells of MED
    !> type `geotype`: entity 0 their integration points (MED_CELL; localisation
    !> `localization`, '' for one point per cell), 4 their nodes (MED_NODE_ELEMENT);
    !> values interlaced (components, points, n); `profile` '' = every cell of the type.
    function parasol_med_write_entity_values(fid, field, numdt, numit, dt, entity, geotype, &
                                             n, profile, localization, values) result(rc) &
        bind(c, name='parasol_med_write_entity_values')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*), profile(*), localization(*)
        integer(c_int), value :: numdt, numit, entity, geotype, n
        real(c_double), value :: dt
        real(c_double), intent(in) :: values(*)
        integer(c_int) :: rc, entitype
        select case (entity)
        case (0)
            entitype = MED_CELL
        case (4)
            entitype = MED_NODE_ELEMENT
        case default
            rc = PLUGIN_BAD_ARGUMENT
            return
        end select
        call quiet_begin()
        rc = MEDfieldValueWithProfileWr(fid, field, numdt, numit, dt, entitype, geotype, &
                                        MED_COMPACT_STMODE, profile, localization, &
                                        MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, n, values)
        call quiet_end()
    end function parasol_med_write_entity_values

    !> Number of computation steps of field `field` (MEDfieldInfoByName).
    function parasol_med_field_step_count(fid, field) result(n) &
        bind(c, name='parasol_med_field_step_count')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*)
        integer(c_int) :: n, ncomponent, localmesh, fieldtype, rc
        character(kind=c_char) :: mesh(MED_NAME_SIZE + 1), dtunit(MED_SNAME_SIZE + 1)
        character(kind=c_char), allocatable :: names(:), units(:)
        call quiet_begin()
        ncomponent = MEDfieldnComponentByName(fid, field)
        call quiet_end()
        if (ncomponent < 0) then
            n = ncomponent
            return
        end if
        allocate (names(MED_SNAME_SIZE * max(ncomponent, 1_c_int) + 1), &
                  units(MED_SNAME_SIZE * max(ncomponent, 1_c_int) + 1))
        n = 0
        call quiet_begin()
        rc = MEDfieldInfoByName(fid, field, mesh, localmesh, fieldtype, names, units, dtunit, n)
        call quiet_end()
        if (rc < 0) n = rc
    end function parasol_med_field_step_count

    !> Step `it` (1-based) of field `field`: its numbers and time (MEDfieldComputingStepInfo).
    function parasol_med_field_step_info(fid, field, it, numdt, numit, dt) result(rc) &
        bind(c, name='parasol_med_field_step_info')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*)
        integer(c_int), value :: it
        integer(c_int), intent(out) :: numdt, numit
        real(c_double), intent(out) :: dt
        integer(c_int) :: rc
        numdt = 0
        numit = 0
        dt = 0.0_c_double
        call quiet_begin()
        rc = MEDfieldComputingStepInfo(fid, field, it, numdt, numit, dt)
        call quiet_end()
    end function parasol_med_field_step_info

    !> Number of (profile, localisation) parts of field `field` at step (numdt, numit) on
    !> cells of MED type `geotype` (entity 0: MED_CELL, 3: MED_NODE, 4: MED_NODE_ELEMENT)
    !> (MEDfieldnProfile).
    function parasol_med_field_profile_count(fid, field, numdt, numit, entity, geotype) &
        result(n) bind(c, name='parasol_med_field_profile_count')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*)
        integer(c_int), value :: numdt, numit, entity, geotype
        integer(c_int) :: n
        character(kind=c_char) :: profile(MED_NAME_SIZE + 1), localization(MED_NAME_SIZE + 1)
        call quiet_begin()
        n = MEDfieldnProfile(fid, field, numdt, numit, entity, geotype, profile, localization)
        call quiet_end()
    end function parasol_med_field_profile_count

    !> Part `profileit` (1-based) of field `field` at a step on an entity and type: its
    !> profile name and size, localisation name and points per entity; the result is the
    !> number of entities (MEDfieldnValueWithProfile, compact storage).
    function parasol_med_field_value_info(fid, field, numdt, numit, entity, geotype, &
                                          profileit, profile, profilesize, localization, &
                                          npoints) result(n) &
        bind(c, name='parasol_med_field_value_info')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*)
        integer(c_int), value :: numdt, numit, entity, geotype, profileit
        character(kind=c_char) :: profile(MED_NAME_SIZE + 1), localization(MED_NAME_SIZE + 1)
        integer(c_int), intent(out) :: profilesize, npoints
        integer(c_int) :: n
        profile = c_null_char
        localization = c_null_char
        profilesize = 0
        npoints = 0
        call quiet_begin()
        n = MEDfieldnValueWithProfile(fid, field, numdt, numit, entity, geotype, profileit, &
                                      MED_COMPACT_STMODE, profile, profilesize, &
                                      localization, npoints)
        call quiet_end()
    end function parasol_med_field_value_info

    !> Reads the values of field `field` at a step on an entity and type, profile `profile`
    !> ('' none), interlaced; `capacity` values the caller's buffer holds, which must be
    !> entities x points x components (parasol_med_field_value_info) (MEDfieldValueWith-
    !> ProfileRd).
    function parasol_med_read_entity_values(fid, field, numdt, numit, entity, geotype, &
                                            profile, capacity, values) result(rc) &
        bind(c, name='parasol_med_read_entity_values')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: field(*), profile(*)
        integer(c_int), value :: numdt, numit, entity, geotype, capacity
        real(c_double) :: values(*)
        integer(c_int) :: rc
        if (capacity < 0) then
            rc = PLUGIN_BAD_ARGUMENT
            return
        end if
        call quiet_begin()
        rc = MEDfieldValueWithProfileRd(fid, field, numdt, numit, entity, geotype, &
                                        MED_COMPACT_STMODE, profile, MED_FULL_INTERLACE, &
                                        MED_ALL_CONSTITUENT, values)
        call quiet_end()
    end function parasol_med_read_entity_values

    !> Reads profile `name` (its entity numbers) into numbers(1:capacity); the result is its
    !> size, or PLUGIN_BAD_SIZE when it holds more than capacity (MEDprofileRd).
    function parasol_med_read_profile(fid, name, capacity, numbers) result(n) &
        bind(c, name='parasol_med_read_profile')
        integer(c_int64_t), value :: fid
        character(kind=c_char), intent(in) :: name(*)
        integer(c_int), value :: capacity
        integer(c_int) :: numbers(*)
        integer(c_int) :: n, rc
        call quiet_begin()
        n = MEDprofileSizeByName(fid, name)
        call quiet_end()
        if (n < 0) return
        if (n > capacity) then
            n = PLUGIN_BAD_SIZE
            return
        end if
        call quiet_begin()
        rc = MEDprofileRd(fid, name, numbers)
        call quiet_end()
        if (rc < 0) n = rc
    end function parasol_med_read_profile

    ! Sends file descriptor 2 (stderr) to /dev/null until quiet_end: MED writes its own
    ! diagnostics there unconditionally, and HDF5 its error stacks.
    subroutine quiet_begin()
        type(c_ptr) :: null_stream
        integer(c_int) :: rc
        if (saved_stderr >= 0) return
        rc = c_fflush(c_null_ptr)
        null_stream = c_fopen('/dev/null' // c_null_char, 'w' // c_null_char)
        if (.not. c_associated(null_stream)) return
        saved_stderr = c_dup(2_c_int)
        if (saved_stderr >= 0) rc = c_dup2(c_fileno(null_stream), 2_c_int)
        rc = c_fclose(null_stream)
    end subroutine quiet_begin

    ! Gives stderr back.
    subroutine quiet_end()
        integer(c_int) :: rc
        if (saved_stderr < 0) return
        rc = c_fflush(c_null_ptr)
        rc = c_dup2(saved_stderr, 2_c_int)
        rc = c_close(saved_stderr)
        saved_stderr = -1
    end subroutine quiet_end

end module parasol_med_plugin
