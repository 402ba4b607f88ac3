!> MED files: the operations the mesh reader (mesh_med_reader) and the result writer
!> (result_med) need, with errors as status_t messages naming the file, the mesh and what
!> could not be read or written. Every count comes back checked for sign; callers check it
!> against what they allocate.
!>
!> The MED library runs in a child process, one per open file (med_server): med_open starts
!> it, each operation is a request and a reply over a socket, med_close ends it. parasol's
!> own process only loads the plug-in and asks its version (med_plugin). So a damaged file
!> that makes HDF5 crash, or a failed write that leaves HDF5 in a state its exit handlers
!> trip on, ends the child, not parasol: the operation under way fails with one message
!> naming the file ("MED file X is damaged: ...", "cannot write X: ..."), and the file is
!> closed exactly once, in the child, or not at all when the child died (doc/stability.md,
!> "Faults"). A write that fails on a system error (a full disk: ENOSPC, EFBIG, EDQUOT)
!> says so in the system's words.
module med_file
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_MESH_ERROR, STATUS_INTERNAL
    use strings, only: string_t, to_text
    use system_error, only: errno_text
    use byte_message, only: message_t
    use child_process, only: child_t, start_child, send_message, receive_message, &
        reap_child, child_end_text
    use med_plugin, only: med_load, med_loaded, med_library_version, MED_PLUGIN_NAME, &
        PLUGIN_BAD_SIZE
    use med_server, only: serve_med, OP_COMPATIBILITY, OP_OPEN, OP_FILE_VERSION, OP_CLOSE, &
        OP_MESH_COUNT, OP_MESH_INFO, OP_MESH_STEP, OP_COUNT, OP_CELL_TYPE, &
        OP_READ_COORDINATES, OP_READ_CONNECTIVITY, OP_READ_NAMES, OP_READ_FAMILIES, &
        OP_FAMILY_COUNT, OP_FAMILY_GROUP_COUNT, OP_FAMILY_INFO, OP_CREATE_MESH, &
        OP_WRITE_COORDINATES, OP_WRITE_CONNECTIVITY, OP_WRITE_NAMES, OP_WRITE_FAMILIES, &
        OP_CREATE_FAMILY, OP_FIELD_COUNT, OP_FIELD_INFO, OP_CREATE_FIELD, OP_PROFILE_COUNT, &
        OP_WRITE_PROFILE, OP_WRITE_FIELD_VALUES, OP_LOCALIZATION_COUNT, OP_LOCALIZATION_NAME, &
        OP_WRITE_LOCALIZATION, OP_WRITE_ENTITY_VALUES, OP_FIELD_STEP_COUNT, OP_FIELD_STEP_INFO, &
        OP_FIELD_PART_COUNT, OP_FIELD_PART_INFO, OP_READ_ENTITY_VALUES, OP_READ_PROFILE, OP_IMPORT
    use med_import, only: make_import_folder, remove_import_folder, IMPORT_TIME_BASE
    use atomic_file, only: track_temporary, untrack_temporary
    implicit none
    private

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
    !> MED versions this build reads: major 3 and 4 (MED-fichier 4.x reads 3.x files); 2.x
    !> files (MED 2.1 to 2.3.6) are read through a copy converted by MED's MEDimport
    !> (med_import).
    integer, parameter :: OLDEST_MAJOR = 3, CONVERTED_MAJOR = 2
    !> errno values that mean the disk (or a limit) refused the data: said in the message.
    integer, parameter :: EIO = 5, EFBIG = 27, ENOSPC = 28, EROFS = 30, EDQUOT = 122
    !> The signal that ends a conversion past its time limit (med_import).
    integer, parameter :: SIGALRM = 14

    !> The server of an open file (med_server) and, once it died, how.
    type :: med_link_t
        type(child_t) :: server
        logical :: lost = .false.                  !< the server died
        character(len=:), allocatable :: lost_how  !< child_end_text of it
    end type med_link_t

    !> An open MED file. A copy is a second handle to the same file (the server is shared).
    type, public :: med_file_t
        character(len=:), allocatable :: path     !< the name messages give
        integer :: mode = MED_READ
        type(med_link_t), pointer :: link => null()
        !> The version of a 2.x file read through a converted copy ("2.3.6"), else ''
        character(len=:), allocatable :: converted_from
        !> The version of that copy ("4.1.0")
        character(len=:), allocatable :: converted_to
    contains
        procedure :: is_open => med_file_is_open
    end type med_file_t

    public :: med_load, med_loaded, med_library_version, MED_PLUGIN_NAME
    public :: med_open, med_close, &
        med_mesh_count, med_mesh_info, med_mesh_step, med_count, med_cell_type, &
        med_read_coordinates, &
        med_read_connectivity, med_read_names, med_read_families, med_family_count, &
        med_family_group_count, med_family_info, med_create_mesh, med_write_coordinates, &
        med_write_connectivity, med_write_names, med_write_families, med_create_family, &
        med_field_count, med_field_info, med_create_field, med_profile_count, &
        med_write_profile, med_write_field_values, med_localization_names, &
        med_write_localization, med_write_entity_values, med_field_steps, &
        med_field_part_count, med_field_part_info, med_read_entity_values, med_read_profile

    !> The operations, in submodules: med_file_mesh (meshes: counts, coordinates,
    !> connectivity, names, families), med_file_fields (fields, profiles, Gauss point
    !> localizations), med_file_requests (the request exchange, failures, buffers). The
    !> session (open, close, versions) is here.
    interface

        !> Number of meshes in the file.
        integer(i4) module function med_mesh_count(file, st) result(n)
            type(med_file_t), intent(in) :: file
            type(status_t), intent(out) :: st
        end function med_mesh_count

        !> Mesh number `it`: name, space dimension, structured (a grid), computation steps.
        !>  st : out, STATUS_MESH_ERROR for a space dimension outside 1..3; read errors
        module subroutine med_mesh_info(file, it, name, spacedim, structured, nstep, st)
            type(med_file_t), intent(in) :: file
            integer(i4), intent(in) :: it
            character(len=:), allocatable, intent(out) :: name
            integer(i4), intent(out) :: spacedim, nstep
            logical, intent(out) :: structured
            type(status_t), intent(out) :: st
        end subroutine med_mesh_info

        !> Computation step `it` of mesh `mesh`: its (numdt, numit).
        module subroutine med_mesh_step(file, mesh, it, numdt, numit, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: it
            integer(i4), intent(out) :: numdt, numit
            type(status_t), intent(out) :: st
        end subroutine med_mesh_step

        !> A count (MED_COUNT_*) of mesh `mesh` at step (numdt, numit); 0 when absent.
        !>  what_text : in, what is counted, for the message
        !>  st        : out, read errors (a negative count from MED)
        integer(i4) module function med_count(file, mesh, numdt, numit, what, geotype, what_text, st) &
            result(n)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, what_text
            integer(i4), intent(in) :: numdt, numit, what, geotype
            type(status_t), intent(out) :: st
        end function med_count

        !> MED type code of cell type number `it` of the mesh (1..MED_COUNT_CELL_TYPES count).
        module subroutine med_cell_type(file, mesh, numdt, numit, it, geotype, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: numdt, numit, it
            integer(i4), intent(out) :: geotype
            type(status_t), intent(out) :: st
        end subroutine med_cell_type

        !> Node coordinates into coords(spacedim * n), interlaced.
        module subroutine med_read_coordinates(file, mesh, numdt, numit, coords, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: numdt, numit
            real(dp), intent(out) :: coords(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_coordinates

        !> Connectivity of the cells of MED type `geotype` into conn(nodes per cell * n).
        module subroutine med_read_connectivity(file, mesh, numdt, numit, geotype, conn, type_name, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, type_name
            integer(i4), intent(in) :: numdt, numit, geotype
            integer(i4), intent(out) :: conn(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_connectivity

        !> The n names of the nodes (MED_NODES) or of the cells of type `geotype` (MED_CELLS),
        !> trailing blanks removed.
        module subroutine med_read_names(file, mesh, numdt, numit, entity, geotype, n, names, &
                                  what_text, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, what_text
            integer(i4), intent(in) :: numdt, numit, entity, geotype, n
            character(len=MED_SNAME_LEN), intent(out) :: names(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_names

        !> Family numbers of the nodes (MED_NODES) or of the cells of type `geotype`.
        module subroutine med_read_families(file, mesh, numdt, numit, entity, geotype, numbers, &
                                     what_text, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, what_text
            integer(i4), intent(in) :: numdt, numit, entity, geotype
            integer(i4), intent(out) :: numbers(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_families

        !> Number of families of mesh `mesh`.
        integer(i4) module function med_family_count(file, mesh, st) result(n)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            type(status_t), intent(out) :: st
        end function med_family_count

        !> Number of groups of family `it` (1-based iterator).
        integer(i4) module function med_family_group_count(file, mesh, it, st) result(n)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: it
            type(status_t), intent(out) :: st
        end function med_family_group_count

        !> Family `it`: name, number, and its groups (size(groups) = its group count, from
        !> med_family_group_count), trailing blanks removed.
        module subroutine med_family_info(file, mesh, it, name, number, groups, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: it
            character(len=:), allocatable, intent(out) :: name
            integer(i4), intent(out) :: number
            character(len=MED_LNAME_LEN), intent(out) :: groups(:)
            type(status_t), intent(out) :: st
        end subroutine med_family_info

        !> Creates unstructured mesh `mesh` of space dimension 2 or 3.
        module subroutine med_create_mesh(file, mesh, spacedim, description, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, description
            integer(i4), intent(in) :: spacedim
            type(status_t), intent(out) :: st
        end subroutine med_create_mesh

        !> Writes the node coordinates coords(spacedim, n).
        module subroutine med_write_coordinates(file, mesh, coords, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            real(dp), intent(in) :: coords(:, :)
            type(status_t), intent(out) :: st
        end subroutine med_write_coordinates

        !> Writes the cells of MED type `geotype`: conn(nodes per cell, n).
        module subroutine med_write_connectivity(file, mesh, geotype, conn, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: geotype
            integer(i4), intent(in) :: conn(:, :)
            type(status_t), intent(out) :: st
        end subroutine med_write_connectivity

        !> Writes entity names (each at most 16 characters).
        module subroutine med_write_names(file, mesh, entity, geotype, names, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: entity, geotype
            character(len=MED_SNAME_LEN), intent(in) :: names(:)
            type(status_t), intent(out) :: st
        end subroutine med_write_names

        !> Writes family numbers of the nodes (MED_NODES) or the cells of type `geotype`.
        module subroutine med_write_families(file, mesh, entity, geotype, numbers, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh
            integer(i4), intent(in) :: entity, geotype
            integer(i4), intent(in) :: numbers(:)
            type(status_t), intent(out) :: st
        end subroutine med_write_families

        !> Creates family `name` (number > 0 nodes, < 0 cells, 0 none) holding `groups`.
        module subroutine med_create_family(file, mesh, name, number, groups, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: mesh, name
            integer(i4), intent(in) :: number
            character(len=MED_LNAME_LEN), intent(in) :: groups(:)
            type(status_t), intent(out) :: st
        end subroutine med_create_family

        !> Number of fields in the file.
        integer(i4) module function med_field_count(file, st) result(n)
            type(med_file_t), intent(in) :: file
            type(status_t), intent(out) :: st
        end function med_field_count

        !> Field `it`: name, mesh and component names (at most `capacity` components).
        !>  components : out, allocated to the field's component count
        module subroutine med_field_info(file, it, name, mesh, components, st)
            type(med_file_t), intent(in) :: file
            integer(i4), intent(in) :: it
            character(len=:), allocatable, intent(out) :: name, mesh
            character(len=MED_SNAME_LEN), allocatable, intent(out) :: components(:)
            type(status_t), intent(out) :: st
        end subroutine med_field_info

        !> Creates float64 field `field` on mesh `mesh` with the given components (no units).
        module subroutine med_create_field(file, field, mesh, components, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field, mesh
            character(len=MED_SNAME_LEN), intent(in) :: components(:)
            type(status_t), intent(out) :: st
        end subroutine med_create_field

        !> Number of profiles in the file.
        integer(i4) module function med_profile_count(file, st) result(n)
            type(med_file_t), intent(in) :: file
            type(status_t), intent(out) :: st
        end function med_profile_count

        !> Writes profile `name`: the node numbers a field is given on.
        module subroutine med_write_profile(file, name, numbers, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: name
            integer(i4), intent(in) :: numbers(:)
            type(status_t), intent(out) :: st
        end subroutine med_write_profile

        !> Writes node field values(components, n) at step (numdt, numit), time dt, on the nodes
        !> of profile `profile` ('' = every node of the mesh).
        module subroutine med_write_field_values(file, field, numdt, numit, dt, values, profile, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field, profile
            integer(i4), intent(in) :: numdt, numit
            real(dp), intent(in) :: dt
            real(dp), intent(in) :: values(:, :)
            type(status_t), intent(out) :: st
        end subroutine med_write_field_values

        !> The names of the Gauss-point localisations in the file.
        module subroutine med_localization_names(file, names, st)
            type(med_file_t), intent(in) :: file
            type(string_t), allocatable, intent(out) :: names(:)
            type(status_t), intent(out) :: st
        end subroutine med_localization_names

        !> Writes Gauss-point localisation `name` on reference cells of MED type `geotype`:
        !> refcoo(dim, nodes) the reference nodes, gscoo(dim, points) the points, their weights.
        module subroutine med_write_localization(file, name, geotype, refcoo, gscoo, weights, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: name
            integer(i4), intent(in) :: geotype
            real(dp), intent(in) :: refcoo(:, :), gscoo(:, :), weights(:)
            type(status_t), intent(out) :: st
        end subroutine med_write_localization

        !> Writes field values on cells of MED type `geotype`: entity MED_ENTITY_CELL (points of
        !> localisation `localization`, '' one per cell) or MED_ENTITY_NODE_ELEMENT (the cells'
        !> nodes); values(components x points, n_cells); profile '' = every cell of the type.
        module subroutine med_write_entity_values(file, field, numdt, numit, dt, entity, geotype, values, &
                                           profile, localization, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field, profile, localization
            integer(i4), intent(in) :: numdt, numit, entity, geotype
            real(dp), intent(in) :: dt
            real(dp), intent(in) :: values(:, :)
            type(status_t), intent(out) :: st
        end subroutine med_write_entity_values

        !> The computation steps of field `field`: numbers and times.
        module subroutine med_field_steps(file, field, numdt, numit, dt, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field
            integer(i4), allocatable, intent(out) :: numdt(:), numit(:)
            real(dp), allocatable, intent(out) :: dt(:)
            type(status_t), intent(out) :: st
        end subroutine med_field_steps

        !> How many (profile, localisation) parts field `field` has at a step on an entity
        !> (MED_ENTITY_*) and MED cell type (0 for nodes).
        integer(i4) module function med_field_part_count(file, field, numdt, numit, entity, geotype, st) &
            result(n)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field
            integer(i4), intent(in) :: numdt, numit, entity, geotype
            type(status_t), intent(out) :: st
        end function med_field_part_count

        !> Part `it` of field `field` at a step on an entity and type: its profile ('' none) and
        !> localisation names, points per entity and number of entities.
        module subroutine med_field_part_info(file, field, numdt, numit, entity, geotype, it, profile, &
                                       localization, n_points, n_entities, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field
            integer(i4), intent(in) :: numdt, numit, entity, geotype, it
            character(len=:), allocatable, intent(out) :: profile, localization
            integer(i4), intent(out) :: n_points, n_entities
            type(status_t), intent(out) :: st
        end subroutine med_field_part_info

        !> Reads the values of part `profile` of field `field` at a step on an entity and type
        !> into values (entities x points x components, interlaced: the caller sizes it from
        !> med_field_part_info).
        module subroutine med_read_entity_values(file, field, numdt, numit, entity, geotype, profile, &
                                          values, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: field, profile
            integer(i4), intent(in) :: numdt, numit, entity, geotype
            real(dp), intent(out) :: values(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_entity_values

        !> Reads profile `name`: the entity numbers (at most `capacity`).
        module subroutine med_read_profile(file, name, capacity, numbers, st)
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: name
            integer(i4), intent(in) :: capacity
            integer(i4), allocatable, intent(out) :: numbers(:)
            type(status_t), intent(out) :: st
        end subroutine med_read_profile

        ! The exchange of one request and its reply with the server, and its failures
        ! (med_file_requests).

        !> Sends a request to the file's server and receives its reply; returns the result code
        !> and leaves the reply at its outputs.
        !>  verb, object : in, what is asked (messages: "cannot read the nodes of mesh M")
        !>  st    : out, the server died (the message says how, naming the file), or the result
        !>          code is < 0 (fail's message) unless check = .false.
        !>  writing : in, optional, the file is being written (default: as its open mode)
        integer(c_int) module function exchange(file, q, r, verb, object, st, check, writing) result(rc)
            type(med_file_t), intent(in) :: file
            type(message_t), intent(in) :: q
            type(message_t), intent(inout) :: r
            character(len=*), intent(in) :: verb, object
            type(status_t), intent(out) :: st
            logical, intent(in), optional :: check, writing
        end function exchange

        module subroutine server_died(st, file, verb, object)
            type(status_t), intent(inout) :: st
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: verb, object
        end subroutine server_died

        module subroutine fail(st, file, verb, object, rc, err, writing)
            type(status_t), intent(inout) :: st
            type(med_file_t), intent(in) :: file
            character(len=*), intent(in) :: verb, object
            integer(c_int), intent(in) :: rc
            integer, intent(in) :: err
            logical, intent(in), optional :: writing
        end subroutine fail

        ! Conversions shared by the submodules (med_file_requests).

        module subroutine quiet_signaling_nans(values)
            real(dp), intent(inout) :: values(:)
        end subroutine quiet_signaling_nans

        module function fixed_chars(names, width) result(buffer)
            character(len=*), intent(in) :: names(:)
            integer, intent(in) :: width
            character(kind=c_char), allocatable :: buffer(:)
        end function fixed_chars

        module function buffer_text(buffer, start, length) result(text)
            character(kind=c_char), intent(in) :: buffer(:)
            integer, intent(in) :: start, length
            character(len=:), allocatable :: text
        end function buffer_text
    end interface

contains

    logical function med_file_is_open(self)
        class(med_file_t), intent(in) :: self
        med_file_is_open = associated(self%link)
    end function med_file_is_open

    !> Opens a MED file: starts its server, then opens the file there.
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
        type(message_t) :: q, r
        integer(c_int) :: rc, hdf_ok, med_ok, major, minor, release
        integer(c_int) :: r_major, r_minor, r_release
        integer(i4) :: lib_major, lib_minor, lib_release
        logical :: exists, in_child
        file%path = path
        file%mode = mode
        file%converted_from = ''
        file%converted_to = ''
        call med_load(st)
        if (st%failed()) return
        if (mode == MED_READ) then
            inquire (file=path, exist=exists)
            if (.not. exists) then
                call set_error(st, STATUS_IO_ERROR, 'MED file ' // path // ' does not exist')
                return
            end if
        end if
        allocate (file%link)
        if (mode == MED_READ) then
            call start_child(file%link%server, in_child, 'reads MED file ' // path, st)
        else
            call start_child(file%link%server, in_child, 'writes MED file ' // path, st)
        end if
        if (in_child) call serve_med(file%link%server%fd)      ! never returns
        if (st%failed()) then
            deallocate (file%link)
            return
        end if
        if (mode == MED_READ) then
            call q%put_int(OP_COMPATIBILITY)
            call q%put_text(path)
            rc = exchange(file, q, r, 'read', 'its header', st, check=.false.)
            if (st%failed()) then
                call med_close(file)
                return
            end if
            hdf_ok = r%get_int()
            med_ok = r%get_int()
            if (hdf_ok == 0) then
                call set_error(st, STATUS_IO_ERROR, path // ' is not a MED file: it is not ' &
                    // 'even an HDF5 file (MED files are HDF5 files; FORMAT=''MED'' reads ' &
                    // 'them; a .mail file is FORMAT=''ASTER'', a .msh FORMAT=''GMSH'')')
            else if (rc < 0) then
                call set_error(st, STATUS_IO_ERROR, path // ' is an HDF5 file but not a MED ' &
                    // 'file: it has no MED version header (MED error ' // &
                    to_text(int(rc, i4)) // ')')
            end if
            if (st%failed()) then
                call med_close(file)
                return
            end if
        end if
        call q%clear()
        call q%put_int(OP_OPEN)
        call q%put_text(path)
        call q%put_int(mode)
        rc = exchange(file, q, r, 'open', 'it', st, check=.false.)
        if (st%ok() .and. rc < 0) then
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
        end if
        if (st%failed()) then
            call med_close(file)
            return
        end if
        if (mode /= MED_READ) return
        call q%clear()
        call q%put_int(OP_FILE_VERSION)
        rc = exchange(file, q, r, 'read', 'its version', st, check=.false.)
        if (st%failed()) then
            call med_close(file)
            return
        end if
        major = r%get_int()
        minor = r%get_int()
        release = r%get_int()
        call med_library_version(lib_major, lib_minor, lib_release, st)
        if (st%failed()) return
        if (rc >= 0 .and. major == CONVERTED_MAJOR) then
            call read_converted(file, r_major, r_minor, r_release, st)
            if (st%failed()) then
                call set_error(st, STATUS_IO_ERROR, 'MED file ' // path // ' was written by ' &
                    // 'MED ' // version_text(major, minor, release, rc) // ', which this ' &
                    // 'parasol cannot read: MED''s converter (MEDimport) could not convert ' &
                    // 'it: ' // st%message)
                call med_close(file)
                return
            end if
            file%converted_from = version_text(major, minor, release, rc)
            rc = 0
            major = r_major
            minor = r_minor
            release = r_release
            med_ok = 1
        end if
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

    ! A 2.x file: its server converts it with MEDimport into a private temporary folder and
    ! reads the copy from then on (med_import); the folder is removed here once the server
    ! has the copy open, or died. major, minor, release: the copy's version. st: why not
    ! (what MEDimport or the system said, or how the server died).
    subroutine read_converted(file, major, minor, release, st)
        type(med_file_t), intent(inout) :: file
        integer(c_int), intent(out) :: major, minor, release
        type(status_t), intent(out) :: st
        type(message_t) :: q, r
        character(len=:), allocatable :: folder, reason
        integer(c_int) :: rc, stage
        major = -1
        minor = -1
        release = -1
        call make_import_folder(folder, st)
        if (st%failed()) return
        ! an interrupt removes the copy, the link and the folder (atomic_file's handler)
        call track_temporary(folder // '/out.med')
        call track_temporary(folder // '/in.med')
        call track_temporary(folder)
        call q%put_int(OP_IMPORT)
        call q%put_text(file%path)
        call q%put_text(folder)
        rc = exchange(file, q, r, 'convert', 'it', st, check=.false.)
        call remove_import_folder(folder)
        call untrack_temporary(folder // '/out.med')
        call untrack_temporary(folder // '/in.med')
        call untrack_temporary(folder)
        if (st%failed()) then
            if (file%link%lost) then
                if (file%link%server%signal == SIGALRM) then
                    call set_error(st, STATUS_IO_ERROR, 'MEDimport did not finish within ' &
                        // 'its time limit (' // to_text(int(IMPORT_TIME_BASE, i4)) // &
                        ' s plus 1 s per MB of the file): it is damaged')
                else
                    call set_error(st, STATUS_IO_ERROR, 'the converter ended (' // &
                        file%link%lost_how // ')')
                end if
            end if
            return
        end if
        stage = r%get_int()
        reason = r%get_text()
        major = r%get_int()
        minor = r%get_int()
        release = r%get_int()
        if (rc >= 0) then
            file%converted_to = version_text(major, minor, release, rc)
            return
        end if
        if (stage == 2) reason = 'the MED library cannot open its converted copy ' // &
            '(MED error ' // to_text(int(rc, i4)) // ')'
        if (len(reason) == 0) reason = 'MED error ' // to_text(int(rc, i4))
        call set_error(st, STATUS_IO_ERROR, reason)
    end subroutine read_converted

    ! Makes every signaling NaN read from a file a quiet one (its bit 51 set): a damaged
    ! file may hold any bit pattern, and the mere test of a signaling NaN (ieee_is_finite,
    ! a comparison) raises IEEE invalid, which the checked build traps (SIGFPE; the fuzzer
    ! found it in a damaged MED 2.3.6 mesh). The readers then refuse it as not finite.
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

    !> Closes the file (a file being written is complete only then) and ends its server.
    !> Closing a file whose server died, or closing twice, does nothing more.
    !>  st : optional, STATUS_IO_ERROR when MED cannot finish writing it
    subroutine med_close(file, st)
        type(med_file_t), intent(inout) :: file
        type(status_t), intent(out), optional :: st
        type(message_t) :: q, r
        type(status_t) :: closing
        integer(c_int) :: rc
        if (.not. associated(file%link)) return
        if (.not. file%link%lost) then
            call q%put_int(OP_CLOSE)
            rc = exchange(file, q, r, 'close', 'it', closing, writing=file%mode /= MED_READ)
        end if
        call reap_child(file%link%server)
        if (closing%ok() .and. .not. file%link%lost .and. &
            (file%link%server%signal /= 0 .or. file%link%server%exit_status /= 0)) then
            file%link%lost = .true.
            file%link%lost_how = child_end_text(file%link%server)
            call server_died(closing, file, 'close', 'it')
        end if
        deallocate (file%link)
        if (present(st)) st = closing
    end subroutine med_close

    ! The file's server died (killed by a signal, or exited) while asked to VERB OBJECT:
    ! "MED file P is damaged: the MED library died reading family 1 of mesh M (killed by
    ! signal 11 (SIGSEGV))", or for a file being written "cannot write P: the MED library
    ! died writing ...".
    ! A failed MED call on the file: "MED file PATH: cannot VERB OBJECT (MED error RC; ...)"
    ! (STATUS_MESH_ERROR: reading, the file's contents are at fault), or for a file being
    ! written "cannot write PATH: <the system's reason> (MED could not VERB OBJECT)" when
    ! the failure came from the disk (errno), else "cannot write PATH: MED could not VERB
    ! OBJECT (MED error RC)" (STATUS_IO_ERROR).
    ! The reply carried the n values asked for (else an internal error: client and server
    ! disagree).
    ! The head of a request on a mesh at a computation step: the operation, the mesh's name,
    ! numdt and numit.
    ! Fixed-width names as one C buffer (each `width` characters, blank-padded), NUL-ended.
    ! Characters start .. start+length-1 of a C buffer, up to the first NUL, trailing blanks
    ! removed.
end module med_file
