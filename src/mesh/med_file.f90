!> MED files through parasol's MED plug-in (libparasol_med.so, plugins/med): the plug-in
!> is the only code linked against Debian's MED library (which pulls HDF5 and OpenMPI, ~10 ms
!> per process start), and it is opened with dlopen (src/core/dynamic_library.f90) the first
!> time a deck reads or writes MED, so decks without MED keep parasol's start-up.
!>
!> This module loads the plug-in once per process (the loaded library is process-wide state,
!> like the dynamic loader's own), checks its ABI version, and offers the MED operations the
!> mesh reader (mesh_med_reader) and the result writer (result_med) need, with errors as
!> status_t messages naming the file, the mesh and what could not be read or written.
!> Every count comes back checked for sign; callers check it against what they allocate.
!>
!> The plug-in is found next to the executable's layout (install_layout: <build>/lib/parasol
!> in the build tree, <prefix>/lib/parasol in an install). Floating-point traps (the Debug
!> build traps invalid, zero and overflow) are switched off during every call into MED and
!> HDF5, whose code is not written for trapping, and the flags are restored afterwards.
module med_file
    use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_char, c_funptr, &
        c_null_char, c_f_procpointer
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_MESH_ERROR
    use strings, only: string_t, to_text
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    use install_layout, only: plugin_file_path
    implicit none
    private

    !> File name of the plug-in and the version of its entry points this module speaks.
    character(len=*), parameter, public :: MED_PLUGIN_NAME = 'libparasol_med.so'
    integer(c_int), parameter :: MED_PLUGIN_ABI = 2
    !> Codes returned by the plug-in itself (not MED's).
    integer(c_int), parameter :: PLUGIN_BAD_SIZE = -900001

    !> Open modes: read, create (replacing any file), add to an existing file.
    integer, parameter, public :: MED_READ = 0, MED_CREATE = 1, MED_APPEND = 2
    !> What med_count counts (see parasol_med_count in the plug-in).
    integer, parameter, public :: MED_COUNT_NODES = 1, MED_COUNT_NODE_NAMES = 2, &
        MED_COUNT_NODE_FAMILIES = 3, MED_COUNT_CELLS = 4, MED_COUNT_CELL_NAMES = 5, &
        MED_COUNT_CELL_FAMILIES = 6, MED_COUNT_CELL_TYPES = 7, MED_COUNT_DESCENDING_CELLS = 8
    !> Entities of names and family numbers.
    integer, parameter, public :: MED_NODES = 1, MED_CELLS = 2
    !> Entities a field's values are on (med.h med_entity_type): the cells' integration
    !> points, the nodes, the cells' nodes (ELNO).
    integer, parameter, public :: MED_ENTITY_CELL = 0, MED_ENTITY_NODE = 3, &
        MED_ENTITY_NODE_ELEMENT = 4
    !> MED string sizes (med.h): object names, entity names, group names.
    integer, parameter, public :: MED_NAME_LEN = 64, MED_SNAME_LEN = 16, MED_LNAME_LEN = 80
    !> MED versions this build reads: major 3 and 4 (MED-fichier 4.x reads 3.x files; 2.x
    !> files need MED's own converter, medimport).
    integer, parameter :: OLDEST_MAJOR = 3

    !> An open MED file.
    type, public :: med_file_t
        character(len=:), allocatable :: path
        integer(c_int64_t) :: fid = -1
    contains
        procedure :: is_open => med_file_is_open
    end type med_file_t

    public :: med_load, med_loaded, med_library_version, med_open, med_close, &
        med_mesh_count, med_mesh_info, med_mesh_step, med_count, med_cell_type, &
        med_read_coordinates, &
        med_read_connectivity, med_read_names, med_read_families, med_family_count, &
        med_family_group_count, med_family_info, med_create_mesh, med_write_coordinates, &
        med_write_connectivity, med_write_names, med_write_families, med_create_family, &
        med_field_count, med_field_info, med_create_field, med_profile_count, &
        med_write_profile, med_write_field_values, med_localization_names, &
        med_write_localization, med_write_entity_values, med_field_steps, &
        med_field_part_count, med_field_part_info, med_read_entity_values, med_read_profile

    abstract interface
        function abi_version_f() result(v) bind(c)
            import :: c_int
            integer(c_int) :: v
        end function abi_version_f
        function version_f(major, minor, release) result(rc) bind(c)
            import :: c_int
            integer(c_int), intent(out) :: major, minor, release
            integer(c_int) :: rc
        end function version_f
        function compatibility_f(path, hdf_ok, med_ok) result(rc) bind(c)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), intent(out) :: hdf_ok, med_ok
            integer(c_int) :: rc
        end function compatibility_f
        function open_f(path, mode, fid) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: mode
            integer(c_int64_t), intent(out) :: fid
            integer(c_int) :: rc
        end function open_f
        function file_version_f(fid, major, minor, release) result(rc) bind(c)
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int), intent(out) :: major, minor, release
            integer(c_int) :: rc
        end function file_version_f
        function fid_f(fid) result(rc) bind(c)
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int) :: rc
        end function fid_f
        function fid_it_f(fid, it) result(rc) bind(c)
            import :: c_int, c_int64_t
            integer(c_int64_t), value :: fid
            integer(c_int), value :: it
            integer(c_int) :: rc
        end function fid_it_f
        function mesh_info_f(fid, it, name, spacedim, meshdim, structured, nstep) &
            result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: it
            character(kind=c_char), intent(out) :: name(*)
            integer(c_int), intent(out) :: spacedim, meshdim, structured, nstep
            integer(c_int) :: rc
        end function mesh_info_f
        function mesh_step_f(fid, mesh, it, numdt, numit) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: it
            integer(c_int), intent(out) :: numdt, numit
            integer(c_int) :: rc
        end function mesh_step_f
        function count_f(fid, mesh, numdt, numit, what, geotype) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit, what, geotype
            integer(c_int) :: n
        end function count_f
        function cell_type_f(fid, mesh, numdt, numit, it, geotype) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit, it
            integer(c_int), intent(out) :: geotype
            integer(c_int) :: rc
        end function cell_type_f
        function read_reals_f(fid, mesh, numdt, numit, values) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit
            real(c_double), intent(out) :: values(*)
            integer(c_int) :: rc
        end function read_reals_f
        function read_connectivity_f(fid, mesh, numdt, numit, geotype, values) result(rc) &
            bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit, geotype
            integer(c_int), intent(out) :: values(*)
            integer(c_int) :: rc
        end function read_connectivity_f
        function read_names_f(fid, mesh, numdt, numit, entity, geotype, names) result(rc) &
            bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit, entity, geotype
            character(kind=c_char), intent(out) :: names(*)
            integer(c_int) :: rc
        end function read_names_f
        function read_families_f(fid, mesh, numdt, numit, entity, geotype, numbers) &
            result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: numdt, numit, entity, geotype
            integer(c_int), intent(out) :: numbers(*)
            integer(c_int) :: rc
        end function read_families_f
        function mesh_count_f(fid, mesh) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int) :: n
        end function mesh_count_f
        function mesh_it_count_f(fid, mesh, it) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: it
            integer(c_int) :: n
        end function mesh_it_count_f
        function family_info_f(fid, mesh, it, capacity, name, number, groups) result(rc) &
            bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: it, capacity
            character(kind=c_char), intent(out) :: name(*), groups(*)
            integer(c_int), intent(out) :: number
            integer(c_int) :: rc
        end function family_info_f
        function create_mesh_f(fid, mesh, spacedim, description) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*), description(*)
            integer(c_int), value :: spacedim
            integer(c_int) :: rc
        end function create_mesh_f
        function write_coordinates_f(fid, mesh, n, values) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: n
            real(c_double), intent(in) :: values(*)
            integer(c_int) :: rc
        end function write_coordinates_f
        function write_connectivity_f(fid, mesh, geotype, n, values) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: geotype, n
            integer(c_int), intent(in) :: values(*)
            integer(c_int) :: rc
        end function write_connectivity_f
        function write_names_f(fid, mesh, entity, geotype, n, names) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*), names(*)
            integer(c_int), value :: entity, geotype, n
            integer(c_int) :: rc
        end function write_names_f
        function write_families_f(fid, mesh, entity, geotype, n, numbers) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*)
            integer(c_int), value :: entity, geotype, n
            integer(c_int), intent(in) :: numbers(*)
            integer(c_int) :: rc
        end function write_families_f
        function create_family_f(fid, mesh, name, number, ngroups, groups) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: mesh(*), name(*), groups(*)
            integer(c_int), value :: number, ngroups
            integer(c_int) :: rc
        end function create_family_f
        function field_info_f(fid, it, capacity, name, mesh, ncomponent, components) &
            result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: it, capacity
            character(kind=c_char), intent(out) :: name(*), mesh(*), components(*)
            integer(c_int), intent(out) :: ncomponent
            integer(c_int) :: rc
        end function field_info_f
        function create_field_f(fid, field, mesh, ncomponent, components, units) result(rc) &
            bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*), mesh(*), components(*), units(*)
            integer(c_int), value :: ncomponent
            integer(c_int) :: rc
        end function create_field_f
        function write_profile_f(fid, name, n, numbers) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: name(*)
            integer(c_int), value :: n
            integer(c_int), intent(in) :: numbers(*)
            integer(c_int) :: rc
        end function write_profile_f
        function write_field_values_f(fid, field, numdt, numit, dt, n, profile, values) &
            result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*), profile(*)
            integer(c_int), value :: numdt, numit, n
            real(c_double), value :: dt
            real(c_double), intent(in) :: values(*)
            integer(c_int) :: rc
        end function write_field_values_f
        function loc_name_f(fid, it, name) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            integer(c_int), value :: it
            character(kind=c_char), intent(out) :: name(*)
            integer(c_int) :: rc
        end function loc_name_f
        function write_loc_f(fid, name, geotype, dim, refcoo, npoints, gscoo, weights) &
            result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: name(*)
            integer(c_int), value :: geotype, dim, npoints
            real(c_double), intent(in) :: refcoo(*), gscoo(*), weights(*)
            integer(c_int) :: rc
        end function write_loc_f
        function write_entity_f(fid, field, numdt, numit, dt, entity, geotype, n, profile, &
                                localization, values) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*), profile(*), localization(*)
            integer(c_int), value :: numdt, numit, entity, geotype, n
            real(c_double), value :: dt
            real(c_double), intent(in) :: values(*)
            integer(c_int) :: rc
        end function write_entity_f
        function field_name_count_f(fid, field) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*)
            integer(c_int) :: n
        end function field_name_count_f
        function step_info_f(fid, field, it, numdt, numit, dt) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*)
            integer(c_int), value :: it
            integer(c_int), intent(out) :: numdt, numit
            real(c_double), intent(out) :: dt
            integer(c_int) :: rc
        end function step_info_f
        function part_count_f(fid, field, numdt, numit, entity, geotype) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*)
            integer(c_int), value :: numdt, numit, entity, geotype
            integer(c_int) :: n
        end function part_count_f
        function part_info_f(fid, field, numdt, numit, entity, geotype, it, profile, &
                             profilesize, localization, npoints) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*)
            integer(c_int), value :: numdt, numit, entity, geotype, it
            character(kind=c_char), intent(out) :: profile(*), localization(*)
            integer(c_int), intent(out) :: profilesize, npoints
            integer(c_int) :: n
        end function part_info_f
        function read_entity_f(fid, field, numdt, numit, entity, geotype, profile, capacity, &
                               values) result(rc) bind(c)
            import :: c_int, c_int64_t, c_char, c_double
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: field(*), profile(*)
            integer(c_int), value :: numdt, numit, entity, geotype, capacity
            real(c_double), intent(out) :: values(*)
            integer(c_int) :: rc
        end function read_entity_f
        function read_profile_f(fid, name, capacity, numbers) result(n) bind(c)
            import :: c_int, c_int64_t, c_char
            integer(c_int64_t), value :: fid
            character(kind=c_char), intent(in) :: name(*)
            integer(c_int), value :: capacity
            integer(c_int), intent(out) :: numbers(*)
            integer(c_int) :: n
        end function read_profile_f
    end interface

    !> The plug-in's entry points, set once by med_load.
    type :: plugin_t
        type(dynamic_library_t) :: library
        logical :: loaded = .false.
        procedure(version_f), pointer, nopass :: library_version => null()
        procedure(compatibility_f), pointer, nopass :: compatibility => null()
        procedure(open_f), pointer, nopass :: open => null()
        procedure(file_version_f), pointer, nopass :: file_version => null()
        procedure(fid_f), pointer, nopass :: close => null()
        procedure(fid_f), pointer, nopass :: mesh_count => null()
        procedure(mesh_info_f), pointer, nopass :: mesh_info => null()
        procedure(mesh_step_f), pointer, nopass :: mesh_step => null()
        procedure(count_f), pointer, nopass :: count => null()
        procedure(cell_type_f), pointer, nopass :: cell_type => null()
        procedure(read_reals_f), pointer, nopass :: read_coordinates => null()
        procedure(read_connectivity_f), pointer, nopass :: read_connectivity => null()
        procedure(read_names_f), pointer, nopass :: read_names => null()
        procedure(read_families_f), pointer, nopass :: read_families => null()
        procedure(mesh_count_f), pointer, nopass :: family_count => null()
        procedure(mesh_it_count_f), pointer, nopass :: family_group_count => null()
        procedure(family_info_f), pointer, nopass :: family_info => null()
        procedure(create_mesh_f), pointer, nopass :: create_mesh => null()
        procedure(write_coordinates_f), pointer, nopass :: write_coordinates => null()
        procedure(write_connectivity_f), pointer, nopass :: write_connectivity => null()
        procedure(write_names_f), pointer, nopass :: write_names => null()
        procedure(write_families_f), pointer, nopass :: write_families => null()
        procedure(create_family_f), pointer, nopass :: create_family => null()
        procedure(fid_f), pointer, nopass :: field_count => null()
        procedure(field_info_f), pointer, nopass :: field_info => null()
        procedure(create_field_f), pointer, nopass :: create_field => null()
        procedure(fid_f), pointer, nopass :: profile_count => null()
        procedure(write_profile_f), pointer, nopass :: write_profile => null()
        procedure(write_field_values_f), pointer, nopass :: write_field_values => null()
        procedure(fid_f), pointer, nopass :: localization_count => null()
        procedure(loc_name_f), pointer, nopass :: localization_name => null()
        procedure(write_loc_f), pointer, nopass :: write_localization => null()
        procedure(write_entity_f), pointer, nopass :: write_entity_values => null()
        procedure(field_name_count_f), pointer, nopass :: field_step_count => null()
        procedure(step_info_f), pointer, nopass :: field_step_info => null()
        procedure(part_count_f), pointer, nopass :: field_profile_count => null()
        procedure(part_info_f), pointer, nopass :: field_value_info => null()
        procedure(read_entity_f), pointer, nopass :: read_entity_values => null()
        procedure(read_profile_f), pointer, nopass :: read_profile => null()
    end type plugin_t

    type(plugin_t), save :: plugin

    !> Floating-point environment around a call into MED (see fp_begin): an opaque C fenv_t
    !> (32 bytes with glibc on x86-64), given room to spare.
    type :: fp_state_t
        integer(c_int64_t) :: env(16) = 0
    end type fp_state_t

    interface
        ! C99 <fenv.h>: save the environment, clear the flags and mask every exception ...
        function c_feholdexcept(env) result(rc) bind(c, name='feholdexcept')
            import :: c_int, c_int64_t
            integer(c_int64_t), intent(out) :: env(*)
            integer(c_int) :: rc
        end function c_feholdexcept
        ! ... and put it back (masks and flags as they were).
        function c_fesetenv(env) result(rc) bind(c, name='fesetenv')
            import :: c_int, c_int64_t
            integer(c_int64_t), intent(in) :: env(*)
            integer(c_int) :: rc
        end function c_fesetenv
    end interface

contains

    !> Loads the MED plug-in (once per process; later calls return at once).
    !>  st   : out, STATUS_IO_ERROR when the plug-in or the MED library cannot be loaded
    !>         (with the loader's reason), or the plug-in is of another version
    !>  path : in, optional, the plug-in file (default: the install layout's plug-in folder)
    subroutine med_load(st, path)
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: path
        character(len=:), allocatable :: file
        type(fp_state_t) :: fp
        procedure(abi_version_f), pointer :: abi_version
        type(c_funptr) :: address
        integer(c_int) :: version
        if (plugin%loaded) return
        if (present(path)) then
            file = path
        else
            file = plugin_file_path(MED_PLUGIN_NAME)
        end if
        call fp_begin(fp)
        call open_library(plugin%library, file, st)   ! runs the libraries' initialisers
        call fp_end(fp)
        if (st%failed()) then
            call set_error(st, STATUS_IO_ERROR, "FORMAT='MED' needs parasol's MED plug-in, " &
                // 'which cannot be loaded: ' // st%message // ' (it is built with parasol ' &
                // 'and needs Debian''s MED library: apt-get install libmedc11)')
            return
        end if
        call find_symbol(plugin%library, 'parasol_med_abi_version', address, st)
        if (st%failed()) return
        call c_f_procpointer(address, abi_version)
        version = abi_version()
        if (version /= MED_PLUGIN_ABI) then
            call set_error(st, STATUS_IO_ERROR, 'the MED plug-in ' // file // ' is of version ' &
                // to_text(int(version, i4)) // ', this parasol needs version ' // &
                to_text(int(MED_PLUGIN_ABI, i4)) // ' (rebuild and reinstall parasol)')
            return
        end if
        call bind_all(st)
        if (st%ok()) plugin%loaded = .true.
    end subroutine med_load

    ! Takes every entry point of the plug-in.
    subroutine bind_all(st)
        type(status_t), intent(out) :: st
        type(c_funptr) :: a
        call find_symbol(plugin%library, 'parasol_med_library_version', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%library_version)
        call find_symbol(plugin%library, 'parasol_med_file_compatibility', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%compatibility)
        call find_symbol(plugin%library, 'parasol_med_open', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%open)
        call find_symbol(plugin%library, 'parasol_med_file_version', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%file_version)
        call find_symbol(plugin%library, 'parasol_med_close', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%close)
        call find_symbol(plugin%library, 'parasol_med_mesh_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%mesh_count)
        call find_symbol(plugin%library, 'parasol_med_mesh_info', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%mesh_info)
        call find_symbol(plugin%library, 'parasol_med_mesh_step', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%mesh_step)
        call find_symbol(plugin%library, 'parasol_med_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%count)
        call find_symbol(plugin%library, 'parasol_med_cell_type', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%cell_type)
        call find_symbol(plugin%library, 'parasol_med_read_coordinates', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_coordinates)
        call find_symbol(plugin%library, 'parasol_med_read_connectivity', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_connectivity)
        call find_symbol(plugin%library, 'parasol_med_read_names', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_names)
        call find_symbol(plugin%library, 'parasol_med_read_families', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_families)
        call find_symbol(plugin%library, 'parasol_med_family_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%family_count)
        call find_symbol(plugin%library, 'parasol_med_family_group_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%family_group_count)
        call find_symbol(plugin%library, 'parasol_med_family_info', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%family_info)
        call find_symbol(plugin%library, 'parasol_med_create_mesh', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%create_mesh)
        call find_symbol(plugin%library, 'parasol_med_write_coordinates', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_coordinates)
        call find_symbol(plugin%library, 'parasol_med_write_connectivity', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_connectivity)
        call find_symbol(plugin%library, 'parasol_med_write_names', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_names)
        call find_symbol(plugin%library, 'parasol_med_write_families', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_families)
        call find_symbol(plugin%library, 'parasol_med_create_family', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%create_family)
        call find_symbol(plugin%library, 'parasol_med_field_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_count)
        call find_symbol(plugin%library, 'parasol_med_field_info', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_info)
        call find_symbol(plugin%library, 'parasol_med_create_field', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%create_field)
        call find_symbol(plugin%library, 'parasol_med_profile_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%profile_count)
        call find_symbol(plugin%library, 'parasol_med_write_profile', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_profile)
        call find_symbol(plugin%library, 'parasol_med_write_field_values', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_field_values)
        call find_symbol(plugin%library, 'parasol_med_localization_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%localization_count)
        call find_symbol(plugin%library, 'parasol_med_localization_name', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%localization_name)
        call find_symbol(plugin%library, 'parasol_med_write_localization', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_localization)
        call find_symbol(plugin%library, 'parasol_med_write_entity_values', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%write_entity_values)
        call find_symbol(plugin%library, 'parasol_med_field_step_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_step_count)
        call find_symbol(plugin%library, 'parasol_med_field_step_info', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_step_info)
        call find_symbol(plugin%library, 'parasol_med_field_profile_count', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_profile_count)
        call find_symbol(plugin%library, 'parasol_med_field_value_info', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%field_value_info)
        call find_symbol(plugin%library, 'parasol_med_read_entity_values', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_entity_values)
        call find_symbol(plugin%library, 'parasol_med_read_profile', a, st)
        if (st%failed()) return
        call c_f_procpointer(a, plugin%read_profile)
    end subroutine bind_all

    !> True once the plug-in is loaded (a deck without MED never loads it).
    logical function med_loaded()
        med_loaded = plugin%loaded
    end function med_loaded

    !> Version of the MED library the plug-in runs with.
    subroutine med_library_version(major, minor, release, st)
        integer(i4), intent(out) :: major, minor, release
        type(status_t), intent(out) :: st
        integer(c_int) :: rc, a, b, c
        type(fp_state_t) :: fp
        major = 0
        minor = 0
        release = 0
        call med_load(st)
        if (st%failed()) return
        call fp_begin(fp)
        rc = plugin%library_version(a, b, c)
        call fp_end(fp)
        if (rc < 0) then
            call set_error(st, STATUS_IO_ERROR, 'the MED library does not report its version')
            return
        end if
        major = a
        minor = b
        release = c
    end subroutine med_library_version

    logical function med_file_is_open(self)
        class(med_file_t), intent(in) :: self
        med_file_is_open = self%fid >= 0
    end function med_file_is_open

    !> Opens a MED file.
    !>  file : out, the open file
    !>  path : in, the file
    !>  mode : in, MED_READ (checked first: exists, is HDF5, is MED of a version this build
    !>         reads, opens), MED_CREATE (replaces any file) or MED_APPEND (an existing file
    !>         written by this MED library; writing an object that exists replaces it, as
    !>         Code_Aster's IMPR_RESU does)
    !>  st   : out, STATUS_IO_ERROR saying what the file is not (no file, not HDF5, not MED,
    !>         MED of version X.Y, damaged or truncated); plug-in load errors
    subroutine med_open(file, path, mode, st)
        type(med_file_t), intent(out) :: file
        character(len=*), intent(in) :: path
        integer, intent(in) :: mode
        type(status_t), intent(out) :: st
        integer(c_int) :: rc, hdf_ok, med_ok, major, minor, release
        integer(i4) :: lib_major, lib_minor, lib_release
        type(fp_state_t) :: fp
        logical :: exists
        file%path = path
        call med_load(st)
        if (st%failed()) return
        if (mode == MED_READ) then
            inquire (file=path, exist=exists)
            if (.not. exists) then
                call set_error(st, STATUS_IO_ERROR, 'MED file ' // path // ' does not exist')
                return
            end if
            call fp_begin(fp)
            rc = plugin%compatibility(path // c_null_char, hdf_ok, med_ok)
            call fp_end(fp)
            if (hdf_ok == 0) then
                call set_error(st, STATUS_IO_ERROR, path // ' is not a MED file: it is not ' &
                    // 'even an HDF5 file (MED files are HDF5 files; FORMAT=''MED'' reads ' &
                    // 'them; a .mail file is FORMAT=''ASTER'', a .msh FORMAT=''GMSH'')')
                return
            else if (rc < 0) then
                call set_error(st, STATUS_IO_ERROR, path // ' is an HDF5 file but not a MED ' &
                    // 'file: it has no MED version header (MED error ' // &
                    to_text(int(rc, i4)) // ')')
                return
            end if
        end if
        call fp_begin(fp)
        rc = plugin%open(path // c_null_char, int(mode, c_int), file%fid)
        call fp_end(fp)
        if (rc < 0 .or. file%fid < 0) then
            file%fid = -1
            select case (mode)
            case (MED_READ)
                call set_error(st, STATUS_IO_ERROR, 'MED file ' // path // ' cannot be ' // &
                    'opened: it is a damaged or truncated HDF5 file, or not a MED file ' // &
                    '(MED error ' // to_text(int(rc, i4)) // ')')
            case default
                call set_error(st, STATUS_IO_ERROR, 'cannot create the MED file ' // path // &
                    ' (check that the output directory exists and is writable; MED error ' &
                    // to_text(int(rc, i4)) // ')')
            end select
            return
        end if
        if (mode /= MED_READ) return
        call fp_begin(fp)
        rc = plugin%file_version(file%fid, major, minor, release)
        call fp_end(fp)
        call med_library_version(lib_major, lib_minor, lib_release, st)
        if (st%failed()) return
        if (rc < 0 .or. major < OLDEST_MAJOR .or. major > lib_major .or. &
            (major == lib_major .and. minor > lib_minor) .or. med_ok == 0) then
            call set_error(st, STATUS_IO_ERROR, 'MED file ' // path // ' was written by MED ' &
                // version_text(major, minor, release, rc) // ', which this parasol cannot ' &
                // 'read: it reads MED ' // to_text(int(OLDEST_MAJOR, i4)) // '.0 to ' // &
                to_text(lib_major) // '.' // to_text(lib_minor) // ' files (MED library ' // &
                to_text(lib_major) // '.' // to_text(lib_minor) // '.' // &
                to_text(lib_release) // '; older files convert with MED''s medimport)')
            call med_close(file)
        end if
    end subroutine med_open

    ! "2.3.6", or "an unknown version" when it could not be read.
    function version_text(major, minor, release, rc) result(text)
        integer(c_int), intent(in) :: major, minor, release, rc
        character(len=:), allocatable :: text
        if (rc < 0 .or. major < 0) then
            text = 'an unknown version'
        else
            text = to_text(int(major, i4)) // '.' // to_text(int(minor, i4)) // '.' // &
                to_text(int(release, i4))
        end if
    end function version_text

    !> Closes the file (a file being written is complete only then).
    !>  st : optional, STATUS_IO_ERROR when MED cannot finish writing it
    subroutine med_close(file, st)
        type(med_file_t), intent(inout) :: file
        type(status_t), intent(out), optional :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        if (.not. file%is_open()) return
        call fp_begin(fp)
        rc = plugin%close(file%fid)
        call fp_end(fp)
        file%fid = -1
        if (rc < 0 .and. present(st)) call set_error(st, STATUS_IO_ERROR, &
            'MED file ' // file%path // ' could not be closed (MED error ' // &
            to_text(int(rc, i4)) // ')')
    end subroutine med_close

    !> Number of meshes in the file.
    integer(i4) function med_mesh_count(file, st) result(n)
        type(med_file_t), intent(in) :: file
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%mesh_count(file%fid)
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count its meshes', n)
    end function med_mesh_count

    !> Mesh number `it`: name, space dimension, structured (a grid), computation steps.
    !>  st : out, STATUS_MESH_ERROR for a space dimension outside 1..3; read errors
    subroutine med_mesh_info(file, it, name, spacedim, structured, nstep, st)
        type(med_file_t), intent(in) :: file
        integer(i4), intent(in) :: it
        character(len=:), allocatable, intent(out) :: name
        integer(i4), intent(out) :: spacedim, nstep
        logical, intent(out) :: structured
        type(status_t), intent(out) :: st
        character(kind=c_char) :: buffer(MED_NAME_LEN + 1)
        integer(c_int) :: rc, sd, md, grid, steps
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%mesh_info(file%fid, int(it, c_int), buffer, sd, md, grid, steps)
        call fp_end(fp)
        name = buffer_text(buffer, 1, MED_NAME_LEN)
        spacedim = sd
        nstep = steps
        structured = grid /= 0
        if (rc == PLUGIN_BAD_SIZE) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                to_text(it) // ' has ' // to_text(spacedim) // ' coordinate axes (a mesh ' // &
                'has 1 to 3)')
        else if (rc < 0) then
            call fail(st, file, 'cannot read the description of mesh ' // to_text(it), rc)
        end if
    end subroutine med_mesh_info

    !> Computation step `it` of mesh `mesh`: its (numdt, numit).
    subroutine med_mesh_step(file, mesh, it, numdt, numit, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: it
        integer(i4), intent(out) :: numdt, numit
        type(status_t), intent(out) :: st
        integer(c_int) :: rc, a, b
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%mesh_step(file%fid, mesh // c_null_char, int(it, c_int), a, b)
        call fp_end(fp)
        numdt = a
        numit = b
        if (rc < 0) call fail(st, file, 'cannot read the computation steps of mesh ' // &
            mesh, rc)
    end subroutine med_mesh_step

    !> A count (MED_COUNT_*) of mesh `mesh` at step (numdt, numit); 0 when absent.
    !>  what_text : in, what is counted, for the message
    !>  st        : out, read errors (a negative count from MED)
    integer(i4) function med_count(file, mesh, numdt, numit, what, geotype, what_text, st) &
        result(n)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, what_text
        integer(i4), intent(in) :: numdt, numit, what, geotype
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%count(file%fid, mesh // c_null_char, int(numdt, c_int), int(numit, c_int), &
                         int(what, c_int), int(geotype, c_int))
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count the ' // what_text // ' of mesh ' // &
            mesh, n)
    end function med_count

    !> MED type code of cell type number `it` of the mesh (1..MED_COUNT_CELL_TYPES count).
    subroutine med_cell_type(file, mesh, numdt, numit, it, geotype, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: numdt, numit, it
        integer(i4), intent(out) :: geotype
        type(status_t), intent(out) :: st
        integer(c_int) :: rc, code
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%cell_type(file%fid, mesh // c_null_char, int(numdt, c_int), &
                              int(numit, c_int), int(it, c_int), code)
        call fp_end(fp)
        geotype = code
        if (rc < 0) call fail(st, file, 'cannot read the cell types of mesh ' // mesh, rc)
    end subroutine med_cell_type

    !> Node coordinates into coords(spacedim * n), interlaced.
    subroutine med_read_coordinates(file, mesh, numdt, numit, coords, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: numdt, numit
        real(dp), intent(out) :: coords(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%read_coordinates(file%fid, mesh // c_null_char, int(numdt, c_int), &
                                     int(numit, c_int), coords)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot read the node coordinates of mesh ' // mesh, rc)
    end subroutine med_read_coordinates

    !> Connectivity of the cells of MED type `geotype` into conn(nodes per cell * n).
    subroutine med_read_connectivity(file, mesh, numdt, numit, geotype, conn, type_name, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, type_name
        integer(i4), intent(in) :: numdt, numit, geotype
        integer(i4), intent(out) :: conn(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%read_connectivity(file%fid, mesh // c_null_char, int(numdt, c_int), &
                                      int(numit, c_int), int(geotype, c_int), conn)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot read the ' // type_name // ' cells of mesh ' // &
            mesh, rc)
    end subroutine med_read_connectivity

    !> The n names of the nodes (MED_NODES) or of the cells of type `geotype` (MED_CELLS),
    !> trailing blanks removed.
    subroutine med_read_names(file, mesh, numdt, numit, entity, geotype, n, names, &
                              what_text, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, what_text
        integer(i4), intent(in) :: numdt, numit, entity, geotype, n
        character(len=MED_SNAME_LEN), intent(out) :: names(:)
        type(status_t), intent(out) :: st
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc
        integer(i4) :: k, j, ios
        type(fp_state_t) :: fp
        allocate (buffer(int(MED_SNAME_LEN, i8) * n + 1), stat=ios)
        if (ios /= 0) then
            call too_big(st, file, what_text // ' names', int(n, i8))
            return
        end if
        call fp_begin(fp)
        rc = plugin%read_names(file%fid, mesh // c_null_char, int(numdt, c_int), &
                               int(numit, c_int), int(entity, c_int), int(geotype, c_int), buffer)
        call fp_end(fp)
        if (rc < 0) then
            call fail(st, file, 'cannot read the names of the ' // what_text // ' of mesh ' // &
                mesh, rc)
            return
        end if
        do k = 1, min(n, size(names, kind=i4))   ! blank-padded fields of 16 characters
            names(k) = transfer(buffer((k - 1) * MED_SNAME_LEN + 1:k * MED_SNAME_LEN), names(k))
            j = index(names(k), c_null_char)      ! a writer that pads with NULs instead
            if (j > 0) names(k)(j:) = ' '
        end do
    end subroutine med_read_names

    !> Family numbers of the nodes (MED_NODES) or of the cells of type `geotype`.
    subroutine med_read_families(file, mesh, numdt, numit, entity, geotype, numbers, &
                                 what_text, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, what_text
        integer(i4), intent(in) :: numdt, numit, entity, geotype
        integer(i4), intent(out) :: numbers(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%read_families(file%fid, mesh // c_null_char, int(numdt, c_int), &
                                  int(numit, c_int), int(entity, c_int), int(geotype, c_int), &
                                  numbers)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot read the family numbers of the ' // &
            what_text // ' of mesh ' // mesh, rc)
    end subroutine med_read_families

    !> Number of families of mesh `mesh`.
    integer(i4) function med_family_count(file, mesh, st) result(n)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%family_count(file%fid, mesh // c_null_char)
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count the families of mesh ' // mesh, n)
    end function med_family_count

    !> Number of groups of family `it` (1-based iterator).
    integer(i4) function med_family_group_count(file, mesh, it, st) result(n)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: it
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%family_group_count(file%fid, mesh // c_null_char, int(it, c_int))
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot read family ' // to_text(it) // ' of mesh ' // &
            mesh, n)
    end function med_family_group_count

    !> Family `it`: name, number, and its groups (size(groups) = its group count, from
    !> med_family_group_count), trailing blanks removed.
    subroutine med_family_info(file, mesh, it, name, number, groups, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: it
        character(len=:), allocatable, intent(out) :: name
        integer(i4), intent(out) :: number
        character(len=MED_LNAME_LEN), intent(out) :: groups(:)
        type(status_t), intent(out) :: st
        character(kind=c_char) :: name_buffer(MED_NAME_LEN + 1)
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc, num
        integer(i4) :: k
        type(fp_state_t) :: fp
        allocate (buffer(MED_LNAME_LEN * max(size(groups), 1) + 1))
        call fp_begin(fp)
        rc = plugin%family_info(file%fid, mesh // c_null_char, int(it, c_int), &
                                int(size(groups), c_int), name_buffer, num, buffer)
        call fp_end(fp)
        name = buffer_text(name_buffer, 1, MED_NAME_LEN)
        number = num
        if (rc < 0) then
            call fail(st, file, 'cannot read family ' // to_text(it) // ' of mesh ' // mesh, rc)
            return
        end if
        do k = 1, size(groups, kind=i4)
            groups(k) = buffer_text(buffer, (k - 1) * MED_LNAME_LEN + 1, MED_LNAME_LEN)
        end do
    end subroutine med_family_info

    !> Creates unstructured mesh `mesh` of space dimension 2 or 3.
    subroutine med_create_mesh(file, mesh, spacedim, description, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, description
        integer(i4), intent(in) :: spacedim
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%create_mesh(file%fid, mesh // c_null_char, int(spacedim, c_int), &
                                description // c_null_char)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot create mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_create_mesh

    !> Writes the node coordinates coords(spacedim, n).
    subroutine med_write_coordinates(file, mesh, coords, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        real(dp), intent(in) :: coords(:, :)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_coordinates(file%fid, mesh // c_null_char, &
                                      int(size(coords, 2), c_int), coords)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write the nodes of mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_write_coordinates

    !> Writes the cells of MED type `geotype`: conn(nodes per cell, n).
    subroutine med_write_connectivity(file, mesh, geotype, conn, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: geotype
        integer(i4), intent(in) :: conn(:, :)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_connectivity(file%fid, mesh // c_null_char, int(geotype, c_int), &
                                       int(size(conn, 2), c_int), conn)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write the cells of mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_write_connectivity

    !> Writes entity names (each at most 16 characters).
    subroutine med_write_names(file, mesh, entity, geotype, names, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: entity, geotype
        character(len=MED_SNAME_LEN), intent(in) :: names(:)
        type(status_t), intent(out) :: st
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc
        integer :: k, j
        type(fp_state_t) :: fp
        allocate (buffer(MED_SNAME_LEN * size(names) + 1))
        do k = 1, size(names)
            do j = 1, MED_SNAME_LEN
                buffer((k - 1) * MED_SNAME_LEN + j) = names(k)(j:j)
            end do
        end do
        buffer(size(buffer)) = c_null_char
        call fp_begin(fp)
        rc = plugin%write_names(file%fid, mesh // c_null_char, int(entity, c_int), &
                                int(geotype, c_int), int(size(names), c_int), buffer)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write entity names of mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_write_names

    !> Writes family numbers of the nodes (MED_NODES) or the cells of type `geotype`.
    subroutine med_write_families(file, mesh, entity, geotype, numbers, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: entity, geotype
        integer(i4), intent(in) :: numbers(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_families(file%fid, mesh // c_null_char, int(entity, c_int), &
                                   int(geotype, c_int), int(size(numbers), c_int), numbers)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write family numbers of mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_write_families

    !> Creates family `name` (number > 0 nodes, < 0 cells, 0 none) holding `groups`.
    subroutine med_create_family(file, mesh, name, number, groups, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh, name
        integer(i4), intent(in) :: number
        character(len=MED_LNAME_LEN), intent(in) :: groups(:)
        type(status_t), intent(out) :: st
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: rc
        integer :: k, j
        type(fp_state_t) :: fp
        allocate (buffer(MED_LNAME_LEN * size(groups) + 1))
        do k = 1, size(groups)
            do j = 1, MED_LNAME_LEN
                buffer((k - 1) * MED_LNAME_LEN + j) = groups(k)(j:j)
            end do
        end do
        buffer(size(buffer)) = c_null_char
        call fp_begin(fp)
        rc = plugin%create_family(file%fid, mesh // c_null_char, name // c_null_char, &
                                  int(number, c_int), int(size(groups), c_int), buffer)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write family ' // name // ' of mesh ' // mesh, rc, &
                              writing=.true.)
    end subroutine med_create_family

    !> Number of fields in the file.
    integer(i4) function med_field_count(file, st) result(n)
        type(med_file_t), intent(in) :: file
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%field_count(file%fid)
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count its fields', n)
    end function med_field_count

    !> Field `it`: name, mesh and component names (at most `capacity` components).
    !>  components : out, allocated to the field's component count
    subroutine med_field_info(file, it, name, mesh, components, st)
        type(med_file_t), intent(in) :: file
        integer(i4), intent(in) :: it
        character(len=:), allocatable, intent(out) :: name, mesh
        character(len=MED_SNAME_LEN), allocatable, intent(out) :: components(:)
        type(status_t), intent(out) :: st
        integer(c_int), parameter :: CAPACITY = 64
        character(kind=c_char) :: name_buffer(MED_NAME_LEN + 1), mesh_buffer(MED_NAME_LEN + 1)
        character(kind=c_char) :: buffer(MED_SNAME_LEN * CAPACITY + 1)
        integer(c_int) :: rc, ncomponent
        integer(i4) :: k
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%field_info(file%fid, int(it, c_int), CAPACITY, name_buffer, mesh_buffer, &
                               ncomponent, buffer)
        call fp_end(fp)
        name = buffer_text(name_buffer, 1, MED_NAME_LEN)
        mesh = buffer_text(mesh_buffer, 1, MED_NAME_LEN)
        allocate (components(0))
        if (rc < 0) then
            call fail(st, file, 'cannot read the description of field ' // to_text(it), rc)
            return
        end if
        deallocate (components)
        allocate (components(ncomponent))
        do k = 1, ncomponent
            components(k) = buffer_text(buffer, (k - 1) * MED_SNAME_LEN + 1, MED_SNAME_LEN)
        end do
    end subroutine med_field_info

    !> Creates float64 field `field` on mesh `mesh` with the given components (no units).
    subroutine med_create_field(file, field, mesh, components, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field, mesh
        character(len=MED_SNAME_LEN), intent(in) :: components(:)
        type(status_t), intent(out) :: st
        character(kind=c_char), allocatable :: names(:), units(:)
        integer(c_int) :: rc
        integer :: k, j
        type(fp_state_t) :: fp
        allocate (names(MED_SNAME_LEN * size(components) + 1))
        allocate (units(MED_SNAME_LEN * size(components) + 1))
        units = ' '
        do k = 1, size(components)
            do j = 1, MED_SNAME_LEN
                names((k - 1) * MED_SNAME_LEN + j) = components(k)(j:j)
            end do
        end do
        names(size(names)) = c_null_char
        units(size(units)) = c_null_char
        call fp_begin(fp)
        rc = plugin%create_field(file%fid, field // c_null_char, mesh // c_null_char, &
                                 int(size(components), c_int), names, units)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot create field ' // field, rc, &
                              writing=.true.)
    end subroutine med_create_field

    !> Number of profiles in the file.
    integer(i4) function med_profile_count(file, st) result(n)
        type(med_file_t), intent(in) :: file
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%profile_count(file%fid)
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count its profiles', n)
    end function med_profile_count

    !> Writes profile `name`: the node numbers a field is given on.
    subroutine med_write_profile(file, name, numbers, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: numbers(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_profile(file%fid, name // c_null_char, int(size(numbers), c_int), &
                                  numbers)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write profile ' // name, rc, &
                              writing=.true.)
    end subroutine med_write_profile

    !> Writes node field values(components, n) at step (numdt, numit), time dt, on the nodes
    !> of profile `profile` ('' = every node of the mesh).
    subroutine med_write_field_values(file, field, numdt, numit, dt, values, profile, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field, profile
        integer(i4), intent(in) :: numdt, numit
        real(dp), intent(in) :: dt
        real(dp), intent(in) :: values(:, :)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_field_values(file%fid, field // c_null_char, int(numdt, c_int), &
                                       int(numit, c_int), real(dt, c_double), &
                                       int(size(values, 2), c_int), profile // c_null_char, &
                                       values)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write field ' // field // ' at step ' // &
            to_text(numdt), rc, writing=.true.)
    end subroutine med_write_field_values

    !> The names of the Gauss-point localisations in the file.
    subroutine med_localization_names(file, names, st)
        type(med_file_t), intent(in) :: file
        type(string_t), allocatable, intent(out) :: names(:)
        type(status_t), intent(out) :: st
        character(kind=c_char) :: buffer(MED_NAME_LEN + 1)
        integer(c_int) :: n, rc, k
        type(fp_state_t) :: fp
        allocate (names(0))
        call fp_begin(fp)
        n = plugin%localization_count(file%fid)
        call fp_end(fp)
        if (n < 0) then
            call fail(st, file, 'cannot count its localisations', n)
            return
        end if
        deallocate (names)
        allocate (names(n))
        do k = 1, n
            call fp_begin(fp)
            rc = plugin%localization_name(file%fid, k, buffer)
            call fp_end(fp)
            if (rc < 0) then
                call fail(st, file, 'cannot read localisation ' // to_text(int(k, i4)), rc)
                return
            end if
            names(k)%s = buffer_text(buffer, 1, MED_NAME_LEN)
        end do
    end subroutine med_localization_names

    !> Writes Gauss-point localisation `name` on reference cells of MED type `geotype`:
    !> refcoo(dim, nodes) the reference nodes, gscoo(dim, points) the points, their weights.
    subroutine med_write_localization(file, name, geotype, refcoo, gscoo, weights, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: geotype
        real(dp), intent(in) :: refcoo(:, :), gscoo(:, :), weights(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        if (size(gscoo, 1) /= size(refcoo, 1) .or. size(gscoo, 2) /= size(weights)) then
            call set_error(st, STATUS_IO_ERROR, 'MED file ' // file%path // ': localisation ' &
                // name // ': inconsistent sizes')
            return
        end if
        call fp_begin(fp)
        rc = plugin%write_localization(file%fid, name // c_null_char, int(geotype, c_int), &
            int(size(refcoo, 1), c_int), refcoo, int(size(weights), c_int), gscoo, weights)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write localisation ' // name, rc, &
                              writing=.true.)
    end subroutine med_write_localization

    !> Writes field values on cells of MED type `geotype`: entity MED_ENTITY_CELL (points of
    !> localisation `localization`, '' one per cell) or MED_ENTITY_NODE_ELEMENT (the cells'
    !> nodes); values(components x points, n_cells); profile '' = every cell of the type.
    subroutine med_write_entity_values(file, field, numdt, numit, dt, entity, geotype, values, &
                                       profile, localization, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field, profile, localization
        integer(i4), intent(in) :: numdt, numit, entity, geotype
        real(dp), intent(in) :: dt
        real(dp), intent(in) :: values(:, :)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        call fp_begin(fp)
        rc = plugin%write_entity_values(file%fid, field // c_null_char, int(numdt, c_int), &
            int(numit, c_int), real(dt, c_double), int(entity, c_int), int(geotype, c_int), &
            int(size(values, 2), c_int), profile // c_null_char, localization // c_null_char, &
            values)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot write field ' // field // ' at step ' // &
            to_text(numdt) // ' on cells of MED type ' // to_text(geotype), rc, writing=.true.)
    end subroutine med_write_entity_values

    !> The computation steps of field `field`: numbers and times.
    subroutine med_field_steps(file, field, numdt, numit, dt, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field
        integer(i4), allocatable, intent(out) :: numdt(:), numit(:)
        real(dp), allocatable, intent(out) :: dt(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: n, k, rc, a, b
        real(c_double) :: t
        type(fp_state_t) :: fp
        allocate (numdt(0), numit(0), dt(0))
        call fp_begin(fp)
        n = plugin%field_step_count(file%fid, field // c_null_char)
        call fp_end(fp)
        if (n < 0) then
            call fail(st, file, 'no field ' // field, n)
            return
        end if
        deallocate (numdt, numit, dt)
        allocate (numdt(n), numit(n), dt(n))
        do k = 1, n
            call fp_begin(fp)
            rc = plugin%field_step_info(file%fid, field // c_null_char, k, a, b, t)
            call fp_end(fp)
            if (rc < 0) then
                call fail(st, file, 'cannot read step ' // to_text(int(k, i4)) // &
                    ' of field ' // field, rc)
                return
            end if
            numdt(k) = a
            numit(k) = b
            dt(k) = t
        end do
    end subroutine med_field_steps

    !> How many (profile, localisation) parts field `field` has at a step on an entity
    !> (MED_ENTITY_*) and MED cell type (0 for nodes).
    integer(i4) function med_field_part_count(file, field, numdt, numit, entity, geotype, st) &
        result(n)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field
        integer(i4), intent(in) :: numdt, numit, entity, geotype
        type(status_t), intent(out) :: st
        type(fp_state_t) :: fp
        call fp_begin(fp)
        n = plugin%field_profile_count(file%fid, field // c_null_char, int(numdt, c_int), &
            int(numit, c_int), int(entity, c_int), int(geotype, c_int))
        call fp_end(fp)
        if (n < 0) call fail(st, file, 'cannot count the parts of field ' // field, n)
    end function med_field_part_count

    !> Part `it` of field `field` at a step on an entity and type: its profile ('' none) and
    !> localisation names, points per entity and number of entities.
    subroutine med_field_part_info(file, field, numdt, numit, entity, geotype, it, profile, &
                                   localization, n_points, n_entities, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field
        integer(i4), intent(in) :: numdt, numit, entity, geotype, it
        character(len=:), allocatable, intent(out) :: profile, localization
        integer(i4), intent(out) :: n_points, n_entities
        type(status_t), intent(out) :: st
        character(kind=c_char) :: pbuf(MED_NAME_LEN + 1), lbuf(MED_NAME_LEN + 1)
        integer(c_int) :: n, size_profile, points
        type(fp_state_t) :: fp
        pbuf = c_null_char
        lbuf = c_null_char
        call fp_begin(fp)
        n = plugin%field_value_info(file%fid, field // c_null_char, int(numdt, c_int), &
            int(numit, c_int), int(entity, c_int), int(geotype, c_int), int(it, c_int), pbuf, &
            size_profile, lbuf, points)
        call fp_end(fp)
        profile = buffer_text(pbuf, 1, MED_NAME_LEN)
        localization = buffer_text(lbuf, 1, MED_NAME_LEN)
        if (profile == 'MED_NO_PROFILE_INTERNAL') profile = ''
        n_points = points
        n_entities = n
        if (n < 0) call fail(st, file, 'cannot read part ' // to_text(it) // ' of field ' // &
            field, n)
    end subroutine med_field_part_info

    !> Reads the values of part `profile` of field `field` at a step on an entity and type
    !> into values (entities x points x components, interlaced: the caller sizes it from
    !> med_field_part_info).
    subroutine med_read_entity_values(file, field, numdt, numit, entity, geotype, profile, &
                                      values, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: field, profile
        integer(i4), intent(in) :: numdt, numit, entity, geotype
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: rc
        type(fp_state_t) :: fp
        if (size(values) > huge(1_c_int)) then
            call too_big(st, file, 'values in field ' // field, int(size(values), i8))
            return
        end if
        call fp_begin(fp)
        rc = plugin%read_entity_values(file%fid, field // c_null_char, int(numdt, c_int), &
            int(numit, c_int), int(entity, c_int), int(geotype, c_int), &
            profile // c_null_char, int(size(values), c_int), values)
        call fp_end(fp)
        if (rc < 0) call fail(st, file, 'cannot read the values of field ' // field, rc)
    end subroutine med_read_entity_values

    !> Reads profile `name`: the entity numbers (at most `capacity`).
    subroutine med_read_profile(file, name, capacity, numbers, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: capacity
        integer(i4), allocatable, intent(out) :: numbers(:)
        type(status_t), intent(out) :: st
        integer(c_int) :: n
        integer(c_int), allocatable :: buffer(:)
        type(fp_state_t) :: fp
        allocate (buffer(max(capacity, 1_i4)))
        call fp_begin(fp)
        n = plugin%read_profile(file%fid, name // c_null_char, int(capacity, c_int), buffer)
        call fp_end(fp)
        if (n < 0) then
            allocate (numbers(0))
            call fail(st, file, 'cannot read profile ' // name, n)
            return
        end if
        numbers = buffer(1:n)
    end subroutine med_read_profile

    ! STATUS_MESH_ERROR "MED file PATH: WHAT (MED error RC)" (reading: the file's contents are
    ! at fault) or STATUS_IO_ERROR (writing).
    subroutine fail(st, file, what, rc, writing)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: what
        integer(c_int), intent(in) :: rc
        logical, intent(in), optional :: writing
        if (present(writing)) then
            call set_error(st, STATUS_IO_ERROR, 'MED file ' // file%path // ': ' // what // &
                ' (MED error ' // to_text(int(rc, i4)) // ')')
        else if (rc == PLUGIN_BAD_SIZE) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': ' // what // &
                ' (it holds more than parasol expects)')
        else
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': ' // what // &
                ' (MED error ' // to_text(int(rc, i4)) // '; the file is damaged, truncated ' &
                // 'or inconsistent)')
        end if
    end subroutine fail

    ! A count too large to hold in memory.
    subroutine too_big(st, file, what, n)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: what
        integer(i8), intent(in) :: n
        call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': it claims ' // &
            to_text(n) // ' ' // what // ', more than this machine can hold')
    end subroutine too_big

    ! Characters start .. start+length-1 of a C buffer, up to the first NUL, trailing blanks
    ! removed.
    function buffer_text(buffer, start, length) result(text)
        character(kind=c_char), intent(in) :: buffer(:)
        integer, intent(in) :: start, length
        character(len=:), allocatable :: text
        integer :: k, n
        n = 0
        do k = start, min(start + length - 1, size(buffer))
            if (buffer(k) == c_null_char) exit
            n = n + 1
        end do
        text = repeat(' ', n)
        do k = 1, n
            text(k:k) = buffer(start + k - 1)
        end do
        text = trim(text)
    end function buffer_text

    ! Saves the floating-point environment and switches traps off before a call into
    ! MED/HDF5 (see the module header). Done through C's <fenv.h>, not the IEEE intrinsic
    ! modules: a Fortran procedure using those gets its halting modes restored on return.
    subroutine fp_begin(state)
        type(fp_state_t), intent(out) :: state
        integer(c_int) :: rc
        rc = c_feholdexcept(state%env)
    end subroutine fp_begin

    ! Restores the traps and flags saved by fp_begin (what MED raised is not parasol's).
    subroutine fp_end(state)
        type(fp_state_t), intent(in) :: state
        integer(c_int) :: rc
        rc = c_fesetenv(state%env)
    end subroutine fp_end

end module med_file
