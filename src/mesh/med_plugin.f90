!> parasol's MED plug-in (libparasol_med.so, plugins/med) as Fortran procedure pointers: the
!> plug-in is the only code linked against Debian's MED library (which pulls HDF5 and
!> OpenMPI, ~10 ms per process start), and it is opened with dlopen
!> (src/core/dynamic_library.f90) the first time a deck reads or writes MED, so decks
!> without MED keep parasol's start-up.
!>
!> This module loads the plug-in once per process (the loaded library is process-wide state,
!> like the dynamic loader's own), checks its ABI version and binds its entry points. Only
!> the MED server (med_server), in a child process, calls the entry points that touch files;
!> parasol's own process loads the plug-in and asks it its version, nothing else
!> (med_file).
!>
!> The plug-in is found next to the executable's layout (install_layout: <build>/lib/parasol
!> in the build tree, <prefix>/lib/parasol in an install). Floating-point traps (the Debug
!> build traps invalid, zero and overflow) are switched off during the calls made here
!> (fp_begin / fp_end); the MED server switches them off for good.
module med_plugin
    use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_char, c_funptr, &
        c_f_procpointer
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use strings, only: to_text
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    use install_layout, only: plugin_file_path
    implicit none
    private

    !> File name of the plug-in and the version of its entry points this module speaks.
    character(len=*), parameter, public :: MED_PLUGIN_NAME = 'libparasol_med.so'
    integer(c_int), parameter :: MED_PLUGIN_ABI = 2
    !> Codes returned by the plug-in itself (not MED's).
    integer(c_int), parameter, public :: PLUGIN_BAD_SIZE = -900001

    public :: med_load, med_loaded, med_library_version, fp_begin, fp_end

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
    type, public :: plugin_t
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

    !> The plug-in's entry points, set once by med_load.
    type(plugin_t), save, public :: plugin

    !> Floating-point environment around a call into MED (see fp_begin): an opaque C fenv_t
    !> (32 bytes with glibc on x86-64), given room to spare.
    type, public :: fp_state_t
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

    !> Saves the floating-point environment and switches traps off before a call into
    !> MED/HDF5 (see the module header). Done through C's <fenv.h>, not the IEEE intrinsic
    !> modules: a Fortran procedure using those gets its halting modes restored on return.
    subroutine fp_begin(state)
        type(fp_state_t), intent(out) :: state
        integer(c_int) :: rc
        rc = c_feholdexcept(state%env)
    end subroutine fp_begin

    !> Restores the traps and flags saved by fp_begin (what MED raised is not parasol's).
    subroutine fp_end(state)
        type(fp_state_t), intent(in) :: state
        integer(c_int) :: rc
        rc = c_fesetenv(state%env)
    end subroutine fp_end

end module med_plugin
