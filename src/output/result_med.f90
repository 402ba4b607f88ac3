!> IMPR_RESU(FORMAT='MED'): meshes and node fields in a MED file, through parasol's MED
!> plug-in (med_file), laid out as Code_Aster writes them (irmhdf, irmmfa, irchme, mdnoch) so
!> that Code_Aster (LIRE_MAILLAGE, LIRE_RESU) and Salome read them:
!>  - the mesh: unstructured, mesh dimension = space dimension (2 or 3), axes X Y Z of
!>    unit INCONNU; nodes in order with their names; cells by type in the order POI1, SEG2,
!>    TRIA3, QUAD4 with their names;
!>  - groups as MED families: the entities with the same set of groups form one family,
!>    numbered in order of first appearance, > 0 for nodes and < 0 for cells, named after
!>    its groups joined by '_' (FAMILLE_<number> when that exceeds 64 characters); entities
!>    in no group are in family 0;
!>  - a node field per result and field name, named by Code_Aster's rule (mdnoch): the
!>    result's name, its first 8 characters padded with '_' to 8, then the field's name
!>    (RESU____DEPL); float64 components DX DY DZ DRX DRY DRZ as the result carries them; one
!>    computation step per stored instant with numdt = numit = NUME_ORDRE and the time INST;
!>    values interlaced, 0 for a component a node lacks (ircmva); written on every node, or
!>    through a profile PROFIL_<8 digits> on the nodes that carry a component (and belong to
!>    the GROUP_NO asked for) when that is not every node (ircmpn, ircmpf).
!> A file is written under a temporary name (<path>.<pid>.partial, as atomic_file) and renamed
!> when complete; adding to a file written earlier in the run copies it first, so a failure
!> never leaves a half-written file under the final name.
module result_med
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_INTERNAL
    use strings, only: string_t, to_text
    use atomic_file, only: delete_file, temporary_path, track_temporary, untrack_temporary, &
        publish_file, scratch_path, copy_file
    use system_error, only: path_kind, folder_of, PATH_FOLDER, PATH_DEVICE
    use mesh_types, only: mesh_t, node_name, cell_name, n_node_groups, n_cell_groups, &
        nodes_of_group, cells_of_group, node_group_name, cell_group_name, N_CELL_TYPES, &
        CELL_TYPE_ORDER, CELL_TYPE_NODES
    use mesh_name_index, only: name_index_t, name_add
    use med_file, only: med_file_t, med_open, med_close, med_mesh_count, med_mesh_info, &
        med_count, med_create_mesh, med_write_coordinates, med_write_connectivity, &
        med_write_names, med_write_families, med_create_family, med_field_count, &
        med_field_info, med_create_field, med_profile_count, med_write_profile, &
        med_write_field_values, med_localization_names, med_write_localization, &
        med_write_entity_values, MED_CREATE, MED_APPEND, MED_COUNT_NODES, MED_NODES, &
        MED_CELLS, MED_NAME_LEN, MED_SNAME_LEN, MED_LNAME_LEN, MED_ENTITY_CELL, &
        MED_ENTITY_NODE_ELEMENT
    use result_data, only: node_field_t
    use mesh_cell_shapes, only: cell_reference_nodes, CELL_TYPE_DIM, CELL_TYPE_NAMES, &
        MAX_CELL_NODES
    use model_types, only: model_t
    use field_types, only: field_t, FIELD_ELGA, FIELD_ELNO
    use element_gauss_families, only: gauss_rule_t, gauss_scheme
    use field_layout, only: element_points
    implicit none
    private

    !> Description stored with each mesh written.
    character(len=*), parameter :: MESH_DESCRIPTION = 'written by parasol'
    !> Name of the family of entities in no group (irmmfa).
    character(len=*), parameter :: NULL_FAMILY = 'FAMILLE_NULLE'
    !> Cell types in the order they are written (Code_Aster's catalogue order, in which
    !> LIRE_MAILLAGE numbers them back), with their MED type codes (med.h).
    integer, parameter :: N_TYPES = N_CELL_TYPES
    integer(i4), parameter :: WRITE_TYPES(N_TYPES) = CELL_TYPE_ORDER
    integer(i4), parameter :: MED_CODES(N_TYPES) = [1, 102, 103, 203, 206, 204, 208, 209]

    type :: int_list_t
        integer(i4), allocatable :: items(:)
    end type int_list_t

    !> A MED file being written (see the module header).
    type, public :: med_output_t
        type(med_file_t) :: file
        character(len=:), allocatable :: path        !< final name
        character(len=:), allocatable :: temp_path   !< written meanwhile
        logical :: to_device = .false.               !< path is a device: copied at commit
        type(string_t), allocatable :: profile_names(:)
        type(int_list_t), allocatable :: profile_nodes(:)
        type(string_t), allocatable :: localizations(:)   !< in the file (read, written)
    end type med_output_t

    !> One instant of an element field to write (write_med_cell_field).
    type, public :: med_cell_step_t
        type(field_t), pointer :: f => null()
        integer(i4) :: numdt = -1
        real(dp) :: time = 0.0_dp
    end type med_cell_step_t

    public :: med_output_open, med_output_commit, med_output_discard, write_med_mesh, &
        med_output_mesh, write_med_node_field, med_field_name, write_med_cell_field, &
        med_localization_name

contains

    !> Opens `path` for writing through `path.<pid>.partial`; a device (/dev/stdout, a FIFO,
    !> /dev/full) through a scratch file (atomic_file's scratch_path) copied to it at commit,
    !> since HDF5 cannot write a device itself.
    !>  append : in, add to the existing file (written earlier in this run) instead of
    !>           replacing it
    !>  st     : out, STATUS_IO_ERROR (output folder missing or not writable, a folder, file
    !>           to add to missing or unreadable, a device to add to); plug-in load errors
    subroutine med_output_open(out, path, append, st)
        type(med_output_t), intent(out) :: out
        character(len=*), intent(in) :: path
        logical, intent(in) :: append
        type(status_t), intent(out) :: st
        integer :: k
        out%path = path
        allocate (out%profile_names(0), out%profile_nodes(0))
        if (path_kind(folder_of(path)) /= PATH_FOLDER) then
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // path // ': No such file ' &
                // 'or directory (its folder ' // folder_of(path) // ' does not exist)')
            return
        end if
        select case (path_kind(path))
        case (PATH_FOLDER)
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // path // ': it is a folder ' &
                // '(a file name is needed here)')
            return
        case (PATH_DEVICE)
            if (append) then
                call set_error(st, STATUS_IO_ERROR, 'cannot add to ' // path // ': a MED ' // &
                    'file written to a device cannot be added to by a later IMPR_RESU (bind ' &
                    // 'the unit to a file)')
                return
            end if
            out%to_device = .true.
            out%temp_path = scratch_path(path)
        case default
            out%temp_path = temporary_path(path)
        end select
        call track_temporary(out%temp_path)
        if (append) then
            call copy_file(path, out%temp_path, path, st)
            if (st%ok()) call med_open(out%file, out%temp_path, MED_APPEND, st)
        else
            call med_open(out%file, out%temp_path, MED_CREATE, st)
        end if
        if (st%failed()) then
            call untrack_temporary(out%temp_path)
            call delete_file(out%temp_path)
            ! messages name the file the user asked for, not its temporary
            k = index(st%message, out%temp_path)
            if (k > 0) st%message = st%message(1:k - 1) // path // &
                st%message(k + len(out%temp_path):)
            return
        end if
        out%file%path = path   ! messages name the file the user asked for
    end subroutine med_output_open

    !> Closes the file and gives it its final name (renamed; copied to a device).
    !>  st : out, STATUS_IO_ERROR when MED cannot finish it, or the rename or copy fails
    !>       ("cannot write PATH: <reason>"); nothing is left under a temporary name
    subroutine med_output_commit(out, st)
        type(med_output_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        call med_close(out%file, st)
        if (st%ok() .and. out%to_device) then
            call copy_file(out%temp_path, out%path, out%path, st)
        else if (st%ok()) then
            call publish_file(out%temp_path, out%path, st)
            return
        end if
        call untrack_temporary(out%temp_path)
        call delete_file(out%temp_path)
    end subroutine med_output_commit

    !> Closes and deletes the temporary file: the final name is left untouched.
    subroutine med_output_discard(out)
        type(med_output_t), intent(inout) :: out
        call med_close(out%file)
        if (.not. allocated(out%temp_path)) return
        call untrack_temporary(out%temp_path)
        call delete_file(out%temp_path)
    end subroutine med_output_discard

    !> The MED field name of field `field` of result `result` (mdnoch): the result name's
    !> first 8 characters padded with '_' to 8, then the field name (RESU____DEPL).
    pure function med_field_name(result, field) result(name)
        character(len=*), intent(in) :: result, field
        character(len=:), allocatable :: name
        character(len=8) :: head
        integer :: k
        head = result(1:min(8, len(result)))
        do k = len_trim(head) + 1, 8
            head(k:k) = '_'
        end do
        name = head // trim(field)
    end function med_field_name

    !> The name under which `mesh` is (or will be) in the file: `wanted` when the file has no
    !> mesh of that name or has one with the same node count (written by an earlier
    !> IMPR_RESU of this run: Code_Aster does not write a mesh twice), else wanted_2, ...
    !>  exists : out, the mesh is already in the file (do not write it again)
    subroutine med_output_mesh(out, mesh, wanted, name, exists, st)
        type(med_output_t), intent(in) :: out
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: wanted
        character(len=:), allocatable, intent(out) :: name
        logical, intent(out) :: exists
        type(status_t), intent(out) :: st
        integer(i4) :: n_meshes, it, suffix, sd, nstep, n_nodes
        character(len=:), allocatable :: this
        logical :: grid, clash
        n_meshes = med_mesh_count(out%file, st)
        if (st%failed()) return
        exists = .false.
        do suffix = 1, n_meshes + 1
            name = wanted
            if (suffix > 1) name = wanted // '_' // to_text(suffix)
            clash = .false.
            do it = 1, n_meshes
                call med_mesh_info(out%file, it, this, sd, grid, nstep, st)
                if (st%failed()) return
                if (this /= name) cycle
                n_nodes = med_count(out%file, name, -1_i4, -1_i4, MED_COUNT_NODES, 0_i4, &
                                    'nodes', st)
                if (st%failed()) return
                if (n_nodes == mesh%n_nodes .and. sd == mesh%dim) then
                    exists = .true.
                    return
                end if
                clash = .true.
            end do
            if (.not. clash) return
        end do
    end subroutine med_output_mesh

    !> Writes `mesh` as MED mesh `name` with its groups as families (module header).
    !>  st : out, STATUS_IO_ERROR for a name MED cannot hold (entity names over 16 characters,
    !>       group names over 80) and write errors
    subroutine write_med_mesh(out, mesh, name, st)
        type(med_output_t), intent(inout) :: out
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: node_family(:), cell_family(:), conn(:, :), numbers(:)
        type(int_list_t), allocatable :: node_family_groups(:), cell_family_groups(:)
        character(len=MED_SNAME_LEN), allocatable :: names(:)
        character(len=MED_LNAME_LEN), allocatable :: no_groups(:)
        real(dp), allocatable :: xyz(:, :)
        integer(i4), allocatable :: cells(:)
        integer(i4) :: k, t, c, np
        call check_names(out, mesh, st)
        if (st%failed()) return
        call med_create_mesh(out%file, name, mesh%dim, MESH_DESCRIPTION, st)
        if (st%failed()) return
        xyz = mesh%coords(1:mesh%dim, 1:mesh%n_nodes)   ! contiguous, as MED reads it
        call med_write_coordinates(out%file, name, xyz, st)
        if (st%failed()) return
        allocate (names(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            names(k) = node_name(mesh, k)
        end do
        call med_write_names(out%file, name, MED_NODES, 0_i4, names, st)
        if (st%failed()) return
        call entity_families(mesh%n_nodes, n_node_groups(mesh), mesh%node_group_ptr, &
                             mesh%node_group_items, 1_i4, node_family, node_family_groups)
        call med_write_families(out%file, name, MED_NODES, 0_i4, node_family, st)
        if (st%failed()) return
        call entity_families(mesh%n_cells, n_cell_groups(mesh), mesh%cell_group_ptr, &
                             mesh%cell_group_items, -1_i4, cell_family, cell_family_groups)
        do t = 1, N_TYPES
            cells = pack([(c, c = 1_i4, mesh%n_cells)], &
                         mesh%cell_type(1:mesh%n_cells) == WRITE_TYPES(t))
            if (size(cells) == 0) cycle
            np = CELL_TYPE_NODES(WRITE_TYPES(t))
            allocate (conn(np, size(cells)))
            deallocate (names)
            allocate (names(size(cells)), numbers(size(cells)))
            do k = 1, size(cells, kind=i4)
                conn(:, k) = mesh%cell_nodes(mesh%cell_ptr(cells(k)):mesh%cell_ptr(cells(k)) &
                                             + np - 1)
                names(k) = cell_name(mesh, cells(k))
                numbers(k) = cell_family(cells(k))
            end do
            call med_write_connectivity(out%file, name, MED_CODES(t), conn, st)
            if (st%ok()) call med_write_names(out%file, name, MED_CELLS, MED_CODES(t), names, st)
            if (st%ok()) call med_write_families(out%file, name, MED_CELLS, MED_CODES(t), &
                                                 numbers, st)
            if (st%failed()) return
            deallocate (conn, numbers)
        end do
        call write_families(out, mesh, name, node_family_groups, .true., st)
        if (st%failed()) return
        call write_families(out, mesh, name, cell_family_groups, .false., st)
        if (st%failed()) return
        allocate (no_groups(0))
        call med_create_family(out%file, name, null_family_name(), 0_i4, no_groups, st)
    end subroutine write_med_mesh

    ! Names MED cannot hold are errors rather than silently cut.
    subroutine check_names(out, mesh, st)
        type(med_output_t), intent(in) :: out
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: k
        do k = 1, mesh%n_nodes
            if (len(node_name(mesh, k)) > MED_SNAME_LEN) then
                call too_long(st, out, 'node', node_name(mesh, k), MED_SNAME_LEN)
                return
            end if
        end do
        do k = 1, mesh%n_cells
            if (len(cell_name(mesh, k)) > MED_SNAME_LEN) then
                call too_long(st, out, 'cell', cell_name(mesh, k), MED_SNAME_LEN)
                return
            end if
        end do
        do k = 1, n_node_groups(mesh)
            if (len(node_group_name(mesh, k)) > MED_LNAME_LEN) then
                call too_long(st, out, 'GROUP_NO', node_group_name(mesh, k), MED_LNAME_LEN)
                return
            end if
        end do
        do k = 1, n_cell_groups(mesh)
            if (len(cell_group_name(mesh, k)) > MED_LNAME_LEN) then
                call too_long(st, out, 'GROUP_MA', cell_group_name(mesh, k), MED_LNAME_LEN)
                return
            end if
        end do
    end subroutine check_names

    subroutine too_long(st, out, what, name, limit)
        type(status_t), intent(inout) :: st
        type(med_output_t), intent(in) :: out
        character(len=*), intent(in) :: what, name
        integer, intent(in) :: limit
        call set_error(st, STATUS_IO_ERROR, 'cannot write ' // out%path // ': ' // what // &
            ' name ' // name // ' has more than the ' // to_text(int(limit, i4)) // &
            ' characters MED holds')
    end subroutine too_long

    ! Families of n entities from their groups (group g holds items(ptr(g):ptr(g+1)-1)):
    ! number(e) = sign * (family in order of first appearance), 0 for entities in no group;
    ! groups(f) lists the groups of family f in increasing group order (irmmf2).
    subroutine entity_families(n, n_groups, ptr, items, sign, number, groups)
        integer(i4), intent(in) :: n, n_groups, ptr(:), items(:), sign
        integer(i4), allocatable, intent(out) :: number(:)
        type(int_list_t), allocatable, intent(out) :: groups(:)
        integer(i4), allocatable :: eptr(:), eitems(:), fill(:)
        type(int_list_t), allocatable :: found(:)
        type(name_index_t) :: signatures
        character(len=:), allocatable :: key
        integer(i4), allocatable :: own(:)
        integer(i4) :: g, e, j, id
        allocate (number(n), eptr(n + 1), found(n))
        number = 0
        eptr = 0
        do g = 1, n_groups
            do j = ptr(g), ptr(g + 1) - 1
                eptr(items(j) + 1) = eptr(items(j) + 1) + 1
            end do
        end do
        eptr(1) = 1
        do e = 1, n
            eptr(e + 1) = eptr(e) + eptr(e + 1)
        end do
        allocate (eitems(eptr(n + 1) - 1), fill(n))
        fill = eptr(1:n)
        do g = 1, n_groups
            do j = ptr(g), ptr(g + 1) - 1
                eitems(fill(items(j))) = g
                fill(items(j)) = fill(items(j)) + 1
            end do
        end do
        do e = 1, n
            if (eptr(e + 1) == eptr(e)) cycle
            own = unique_sorted(eitems(eptr(e):eptr(e + 1) - 1))
            key = ''
            do j = 1, size(own, kind=i4)
                key = key // to_text(own(j)) // ','
            end do
            call name_add(signatures, key, id)
            if (id > 0) found(id)%items = own
            number(e) = sign * abs(id)
        end do
        groups = found(1:signatures%count)
    end subroutine entity_families

    ! The distinct values of a non-decreasing list (an entity listed twice in a group).
    pure function unique_sorted(values) result(unique)
        integer(i4), intent(in) :: values(:)
        integer(i4), allocatable :: unique(:)
        integer :: k
        unique = pack(values, [.true., (values(k) /= values(k - 1), k = 2, size(values))])
    end function unique_sorted

    ! Writes the node (nodes = .true.) or cell families: number +-f, groups, name.
    subroutine write_families(out, mesh, name, families, nodes, st)
        type(med_output_t), intent(in) :: out
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(int_list_t), intent(in) :: families(:)
        logical, intent(in) :: nodes
        type(status_t), intent(out) :: st
        type(name_index_t) :: used
        character(len=MED_LNAME_LEN), allocatable :: groups(:)
        character(len=:), allocatable :: family
        integer(i4) :: f, g, number, id
        do f = 1, size(families, kind=i4)
            number = f
            if (.not. nodes) number = -f
            allocate (groups(size(families(f)%items)))
            family = ''
            do g = 1, size(groups)
                if (nodes) then
                    groups(g) = node_group_name(mesh, families(f)%items(g))
                else
                    groups(g) = cell_group_name(mesh, families(f)%items(g))
                end if
                if (g > 1) family = family // '_'
                family = family // trim(groups(g))
            end do
            if (len(family) > MED_NAME_LEN) family = 'FAMILLE_' // to_text(number)
            call name_add(used, family, id)
            if (id < 0) then   ! two group sets joined to the same name (A_B and {A, B})
                family = 'FAMILLE_' // to_text(number)
                call name_add(used, family, id)
            end if
            call med_create_family(out%file, name, family, number, groups, st)
            if (st%failed()) return
            deallocate (groups)
        end do
    end subroutine write_families

    ! FAMILLE_NULLE padded with '_' to 64 characters, as Code_Aster names it (irmmfa).
    pure function null_family_name() result(name)
        character(len=MED_NAME_LEN) :: name
        name = repeat('_', MED_NAME_LEN)
        name(1:len(NULL_FAMILY)) = NULL_FAMILY
    end function null_family_name

    !> Writes one node field: `steps(k)` at computation step numdt(k) = numit, time times(k).
    !>  mesh_name : in, the MED mesh it lives on (already in the file)
    !>  field     : in, the MED field name (med_field_name)
    !>  selected  : in, (n_nodes) nodes asked for (GROUP_NO); the field is written on those
    !>              that carry one of its components
    !>  st        : out, STATUS_IO_ERROR: the file already has this field with other
    !>              components or on another mesh, or already holds one of the steps; no node
    !>              to write; write errors
    subroutine write_med_node_field(out, mesh_name, field, steps, numdt, times, selected, st)
        type(med_output_t), intent(inout) :: out
        character(len=*), intent(in) :: mesh_name, field
        type(node_field_t), intent(in) :: steps(:)
        integer(i4), intent(in) :: numdt(:)
        real(dp), intent(in) :: times(:)
        logical, intent(in) :: selected(:)
        type(status_t), intent(out) :: st
        character(len=MED_SNAME_LEN), allocatable :: components(:)
        integer(i4), allocatable :: nodes(:)
        real(dp), allocatable :: values(:, :)
        character(len=:), allocatable :: profile
        logical, allocatable :: written(:)
        logical :: exists
        integer(i4) :: k, c, n_cmp
        if (size(steps) == 0 .or. size(steps) /= size(numdt) .or. size(steps) /= size(times)) &
            then
            call set_error(st, STATUS_INTERNAL, 'MED field ' // field // ': one time and ' // &
                'one step number per instant are needed')
            return
        end if
        n_cmp = size(steps(1)%components, kind=i4)
        allocate (components(n_cmp))
        do c = 1, n_cmp
            components(c) = steps(1)%components(c)%s
        end do
        written = selected .and. any(steps(1)%mask, dim=1)
        nodes = pack([(k, k = 1_i4, size(selected, kind=i4))], written)
        if (size(nodes) == 0) then
            call set_error(st, STATUS_IO_ERROR, 'MED field ' // field // ': no node asked ' // &
                'for carries its components; nothing to write')
            return
        end if
        call find_field(out, mesh_name, field, components, exists, st)
        if (st%failed()) return
        if (.not. exists) call med_create_field(out%file, field, mesh_name, components, st)
        if (st%failed()) return
        profile = ''
        if (size(nodes) < size(selected)) then
            call node_profile(out, nodes, profile, st)
            if (st%failed()) return
        end if
        allocate (values(n_cmp, size(nodes)))
        do k = 1, size(steps, kind=i4)
            do c = 1, n_cmp
                values(c, :) = merge(steps(k)%values(c, nodes), 0.0_dp, steps(k)%mask(c, nodes))
            end do
            call med_write_field_values(out%file, field, numdt(k), numdt(k), times(k), values, &
                                        profile, st)
            if (st%failed()) then
                if (exists) st%message = st%message // ' (the file may already hold this ' // &
                    'step of ' // field // ': each instant is written once per file)'
                return
            end if
        end do
    end subroutine write_med_node_field

    !> Code_Aster's name of a Gauss-point localisation (irmpg1): the element reference's
    !> name (TR3, QU4, ...) on 8 characters, the family's (FPG4, NOEU, ...), blanks turned to
    !> '_' up to the last non-blank; with sub-points (plate layers, written as points, the
    !> sub-points of each point in turn) their count right-aligned in columns 17-24 and
    !> ASTER_SP in 33-40, every blank of the 40 turned to '_'.
    pure function med_localization_name(cell_type, family, n_sub) result(name)
        integer(i4), intent(in) :: cell_type, n_sub
        character(len=*), intent(in) :: family
        character(len=:), allocatable :: name
        character(len=40) :: text
        character(len=8) :: digits
        integer :: k, last
        text = ''
        text(1:8) = element_reference(cell_type)
        text(9:16) = family
        last = len_trim(text)
        if (n_sub > 1) then
            write (digits, '(i8)') n_sub
            text(17:24) = digits
            text(33:40) = 'ASTER_SP'
            last = 40
        end if
        do k = 1, last
            if (text(k:k) == ' ') text(k:k) = '_'
        end do
        name = text(1:last)
    end function med_localization_name

    ! Code_Aster's name of the reference element of a cell type.
    pure function element_reference(cell_type) result(name)
        integer(i4), intent(in) :: cell_type
        character(len=3) :: name
        select case (trim(CELL_TYPE_NAMES(cell_type)))
        case ('POI1')
            name = 'PO1'
        case ('SEG2')
            name = 'SE2'
        case ('SEG3')
            name = 'SE3'
        case ('TRIA3')
            name = 'TR3'
        case ('TRIA6')
            name = 'TR6'
        case ('QUAD4')
            name = 'QU4'
        case ('QUAD8')
            name = 'QU8'
        case default
            name = 'QU9'
        end select
    end function element_reference

    !> Writes an element field (ELGA, ELNO, ELEM or CART) as Code_Aster does (irceme,
    !> ircame, irmpga): ELGA on the cells' integration points, one localisation per
    !> reference element, family and sub-point count (med_localization_name; the points of
    !> the element family with that many points, field_layout element_points; sub-points
    !> written as points), ELNO on the cells' nodes (MED_NODE_ELEMENT), ELEM and CART one
    !> value set per cell; ELNO (ELEM) with sub-points on integration points at the nodes
    !> (the centre), localisation NOEU (FPG1) with the sub-points; per cell type and layout, a profile of the cells written when
    !> not all of that type are. A component a cell lacks is written 0.
    !>  cols     : in, the field's components written, in that order
    !>  taken    : in, (n_cells) the cells asked for (GROUP_MA)
    !>  model    : in, the elements of the cells (the points of an ELGA field); may be null
    !>             for other locations
    !>  st       : out, STATUS_IO_ERROR: an ELGA field whose points cannot be located, no
    !>             cell to write, write errors
    subroutine write_med_cell_field(out, mesh, model, mesh_name, field, steps, cols, taken, st)
        type(med_output_t), intent(inout) :: out
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        character(len=*), intent(in) :: mesh_name, field
        type(med_cell_step_t), intent(in) :: steps(:)
        integer(i4), intent(in) :: cols(:)
        logical, intent(in) :: taken(:)
        type(status_t), intent(out) :: st
        character(len=MED_SNAME_LEN), allocatable :: components(:)
        integer(i4), allocatable :: rank(:), members(:), numbers(:)
        logical, allocatable :: done(:)
        real(dp), allocatable :: values(:, :)
        character(len=:), allocatable :: profile, localization
        integer(i4) :: k, t, c, c0, j, n_cells_type, n_val, entity, ctype, m
        integer(i4) :: counts(N_TYPES)
        logical :: exists, wrote
        integer(i4) :: location
        location = steps(1)%f%location
        allocate (components(size(cols)))
        do j = 1, size(cols, kind=i4)
            components(j) = steps(1)%f%components(cols(j))%s
        end do
        call find_field(out, mesh_name, field, components, exists, st)
        if (st%failed()) return
        if (.not. exists) call med_create_field(out%file, field, mesh_name, components, st)
        if (st%failed()) return
        ! the rank of each cell among the cells of its type (MED numbers cells by type)
        allocate (rank(mesh%n_cells))
        counts = 0
        do c = 1, mesh%n_cells
            t = findloc(WRITE_TYPES, mesh%cell_type(c), dim=1)
            counts(t) = counts(t) + 1
            rank(c) = counts(t)
        end do
        wrote = .false.
        do k = 1, size(steps, kind=i4)
            associate (f => steps(k)%f)
                allocate (done(mesh%n_cells))
                done = .not. (f%n_points(1:mesh%n_cells) > 0 .and. taken(1:mesh%n_cells))
                do c0 = 1, mesh%n_cells
                    if (done(c0)) cycle
                    ! the cells laid out as c0: same type, points and sub-points
                    ctype = mesh%cell_type(c0)
                    t = findloc(WRITE_TYPES, ctype, dim=1)
                    members = pack([(c, c = c0, mesh%n_cells)], .not. done(c0:mesh%n_cells) &
                        .and. mesh%cell_type(c0:mesh%n_cells) == ctype .and. &
                        f%n_points(c0:mesh%n_cells) == f%n_points(c0) .and. &
                        f%n_subpoints(c0:mesh%n_cells) == f%n_subpoints(c0))
                    done(members) = .true.
                    localization = ''
                    entity = MED_ENTITY_CELL
                    if (location == FIELD_ELNO) entity = MED_ENTITY_NODE_ELEMENT
                    if (CELL_TYPE_DIM(ctype) > 0) then
                        if (location == FIELD_ELGA) then
                            call ensure_localization(out, model, mesh, c0, f%n_points(c0), &
                                f%n_subpoints(c0), '', localization, st)
                        else if (f%n_subpoints(c0) > 1) then
                            ! sub-points at the nodes (or the centre): integration points
                            ! at those places
                            entity = MED_ENTITY_CELL
                            call ensure_localization(out, model, mesh, c0, f%n_points(c0), &
                                f%n_subpoints(c0), trim(merge('NOEU', 'FPG1', &
                                location == FIELD_ELNO)), localization, st)
                        end if
                        if (st%failed()) return
                    end if
                    n_val = size(cols, kind=i4) * f%n_points(c0) * f%n_subpoints(c0)
                    allocate (values(n_val, size(members)))
                    do m = 1, size(members, kind=i4)
                        call cell_values(f, members(m), cols, values(:, m))
                    end do
                    n_cells_type = counts(t)
                    profile = ''
                    if (size(members) < n_cells_type) then
                        numbers = rank(members)
                        call node_profile(out, numbers, profile, st)
                        if (st%failed()) return
                    end if
                    call med_write_entity_values(out%file, field, steps(k)%numdt, &
                        steps(k)%numdt, steps(k)%time, entity, MED_CODES(t), values, profile, &
                        localization, st)
                    deallocate (values)
                    if (st%failed()) then
                        if (exists) st%message = st%message // ' (the file may already ' // &
                            'hold this step of ' // field // ': each instant is written ' // &
                            'once per file)'
                        return
                    end if
                    wrote = .true.
                end do
                deallocate (done)
            end associate
        end do
        if (.not. wrote) call set_error(st, STATUS_IO_ERROR, 'MED field ' // field // &
            ': no cell asked for carries it; nothing to write')
    end subroutine write_med_cell_field

    ! The values of cell c, point by point, sub-point by sub-point, the components `cols`
    ! (0 for one the cell lacks).
    subroutine cell_values(f, c, cols, v)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: c, cols(:)
        real(dp), intent(out) :: v(:)
        integer(i4) :: p, s, j, q, nc, slot
        integer(i8) :: base
        v = 0.0_dp
        nc = size(f%sets(f%cell_set(c))%cmp, kind=i4)
        do j = 1, size(cols, kind=i4)
            slot = 0
            do q = 1, nc
                if (f%sets(f%cell_set(c))%cmp(q) == cols(j)) slot = q
            end do
            if (slot == 0) cycle
            do p = 1, f%n_points(c)
                do s = 1, f%n_subpoints(c)
                    base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * nc
                    v(((p - 1) * f%n_subpoints(c) + (s - 1)) * size(cols) + j) = &
                        f%values(base + slot)
                end do
            end do
        end do
    end subroutine cell_values

    ! The localisation of the integration points of cell c (n_points points, n_sub
    ! sub-points each), written to the file unless it holds it already.
    subroutine ensure_localization(out, model, mesh, c, n_points, n_sub, scheme, name, st)
        type(med_output_t), intent(inout) :: out
        type(model_t), pointer, intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c, n_points, n_sub
        character(len=*), intent(in) :: scheme
        character(len=:), allocatable, intent(out) :: name
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp) :: nodes(2, MAX_CELL_NODES)
        real(dp), allocatable :: gscoo(:, :), weights(:), refcoo(:, :)
        type(string_t), allocatable :: more(:)
        integer(i4) :: ctype, dim, nn, p, s, k
        name = ''
        ctype = mesh%cell_type(c)
        if (len(scheme) > 0) then
            call gauss_scheme(ctype, scheme, rule, st)
        else if (.not. associated(model)) then
            call set_error(st, STATUS_IO_ERROR, 'an ELGA field whose model is not known: ' // &
                'its Gauss points cannot be located in MED')
            return
        else
            call element_points(model%element(c), ctype, n_points, rule, st)
        end if
        if (st%failed()) then
            st%code = STATUS_IO_ERROR
            st%message = 'cell ' // cell_name(mesh, c) // ': ' // st%message
            return
        end if
        name = med_localization_name(ctype, rule%scheme, n_sub)
        if (.not. allocated(out%localizations)) then
            call med_localization_names(out%file, out%localizations, st)
            if (st%failed()) return
        end if
        do k = 1, size(out%localizations)
            if (out%localizations(k)%s == name) return
        end do
        dim = CELL_TYPE_DIM(ctype)
        nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        call cell_reference_nodes(ctype, nodes)
        allocate (gscoo(dim, n_points * n_sub), weights(n_points * n_sub))
        do p = 1, n_points
            do s = 1, n_sub
                gscoo(:, (p - 1) * n_sub + s) = rule%xi(1:dim, p)
                weights((p - 1) * n_sub + s) = rule%w(p)
            end do
        end do
        refcoo = nodes(1:dim, 1:nn)         ! contiguous, as MED reads it
        call med_write_localization(out%file, name, MED_CODES(findloc(WRITE_TYPES, ctype, &
            dim=1)), refcoo, gscoo, weights, st)
        if (st%failed()) return
        allocate (more(size(out%localizations) + 1))
        more(1:size(out%localizations)) = out%localizations
        more(size(more))%s = name
        call move_alloc(more, out%localizations)
    end subroutine ensure_localization

    ! Whether the file has field `field` (from an earlier IMPR_RESU of this run); it must
    ! then be on the same mesh with the same components.
    subroutine find_field(out, mesh_name, field, components, exists, st)
        type(med_output_t), intent(in) :: out
        character(len=*), intent(in) :: mesh_name, field
        character(len=MED_SNAME_LEN), intent(in) :: components(:)
        logical, intent(out) :: exists
        type(status_t), intent(out) :: st
        integer(i4) :: n, it
        character(len=:), allocatable :: name, mesh
        character(len=MED_SNAME_LEN), allocatable :: found(:)
        exists = .false.
        n = med_field_count(out%file, st)
        if (st%failed()) return
        do it = 1, n
            call med_field_info(out%file, it, name, mesh, found, st)
            if (st%failed()) return
            if (name /= field) cycle
            exists = .true.
            if (mesh /= mesh_name .or. size(found) /= size(components)) then
                call mismatch()
            else if (any(found /= components)) then
                call mismatch()
            end if
            return
        end do
    contains
        subroutine mismatch()
            call set_error(st, STATUS_IO_ERROR, out%path // ' already has a field ' // field &
                // ' on mesh ' // mesh // ' with other components: write this one to ' // &
                'another unit')
        end subroutine mismatch
    end subroutine find_field

    ! The profile holding `nodes`: one written before in this file session, or a new one
    ! named PROFIL_<8 digits> after the profiles already in the file (ircmpf).
    subroutine node_profile(out, nodes, name, st)
        type(med_output_t), intent(inout) :: out
        integer(i4), intent(in) :: nodes(:)
        character(len=:), allocatable, intent(out) :: name
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        type(int_list_t), allocatable :: lists(:)
        character(len=8) :: digits
        integer(i4) :: k, n
        do k = 1, size(out%profile_names, kind=i4)
            if (size(out%profile_nodes(k)%items) /= size(nodes)) cycle
            if (all(out%profile_nodes(k)%items == nodes)) then
                name = out%profile_names(k)%s
                return
            end if
        end do
        n = med_profile_count(out%file, st)
        if (st%failed()) return
        write (digits, '(i8.8)') n + 1
        name = 'PROFIL_' // digits
        if (len(name) > MED_NAME_LEN) name = name(1:MED_NAME_LEN)
        call med_write_profile(out%file, name, nodes, st)
        if (st%failed()) return
        n = size(out%profile_names, kind=i4)
        allocate (names(n + 1), lists(n + 1))
        names(1:n) = out%profile_names
        lists(1:n) = out%profile_nodes
        names(n + 1)%s = name
        lists(n + 1)%items = nodes
        call move_alloc(names, out%profile_names)
        call move_alloc(lists, out%profile_nodes)
    end subroutine node_profile

end module result_med
