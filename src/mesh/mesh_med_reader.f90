!> Reader of MED meshes (LIRE_MAILLAGE FORMAT='MED'), through parasol's MED plug-in
!> (med_file). What it reads is what Code_Aster reads (code_aster 17 MeshReader::_readMesh,
!> and lrmmno/lrmmma for names, U7.01.21):
!>  - the mesh named NOM_MED, else the file's only mesh (Code_Aster takes the first one; a
!>    file with several meshes and no NOM_MED is an error here, listing their names);
!>  - its first computation step; its space dimension (2 or 3) is the mesh's dimension;
!>  - nodes in file order; cells by type in Code_Aster's catalogue order POI1, SEG2, SEG3,
!>    TRIA3, TRIA6, QUAD4, QUAD8, QUAD9 (MeshReader's asterTypeList), in file order within a
!>    type; MED's node order within a cell is Code_Aster's for these types (Code_Aster
!>    permutes only 3D types). Other cell types are refused by their Code_Aster names;
!>  - node and cell names: N<number> and M<number> with the numbers of the order above,
!>    whatever names the file stores: code_aster 17 keeps no entity names (BaseMesh::
!>    buildNamesVectors does nothing; a deck's MAILLE='M23' is cell 23 in that order, as
!>    ssls100a's cells M23-M98 are its TRIA3 after 22 SEG2 the file names M77-M98);
!>  - groups from the families: a family with a number > 0 is a set of nodes, < 0 a set of
!>    cells; each of its groups is a GROUP_NO or GROUP_MA holding those entities. Groups are
!>    created in the order they first appear in the families, members in increasing order;
!>    empty groups are dropped, and so are groups with names longer than 24 characters
!>    (Code_Aster's limit; a note in the .mess says so).
!> Every count read from the file is checked before anything is allocated or indexed with
!> it: against the other counts (as many names and family numbers as entities), against the
!> node count (connectivity), against the families defined (family numbers), and against
!> what fits in memory.
module mesh_med_reader
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: string_t, to_text, starts_with
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, CELL_TYPE_ORDER, &
        CELL_TYPE_NODES, MAX_CELL_NODES
    use mesh_name_index, only: name_index_t, name_add, name_of
    use med_file, only: med_file_t, med_load, med_open, med_close, med_mesh_count, med_mesh_info, &
        med_mesh_step, med_count, med_cell_type, med_read_coordinates, med_read_connectivity, &
        med_read_names, med_read_families, med_family_count, med_family_group_count, &
        med_family_info, MED_READ, MED_COUNT_NODES, MED_COUNT_NODE_NAMES, &
        MED_COUNT_NODE_FAMILIES, MED_COUNT_CELLS, MED_COUNT_CELL_NAMES, &
        MED_COUNT_CELL_FAMILIES, MED_COUNT_CELL_TYPES, MED_COUNT_DESCENDING_CELLS, &
        MED_NODES, MED_CELLS, MED_SNAME_LEN, MED_LNAME_LEN
    implicit none
    private

    !> Longest group name Code_Aster keeps (MeshReader: longer ones are dropped, MED_7).
    integer, parameter, public :: MED_GROUP_NAME_MAX = 24
    !> Most groups one family may hold (a sanity bound on a count read from the file).
    integer(i4), parameter :: MAX_GROUPS_PER_FAMILY = 100000

    !> MED cell types (med.h) with their Code_Aster names; the first eight are the ones
    !> parasol reads, in Code_Aster's catalogue order (CELL_TYPE_ORDER), in which its
    !> MeshReader numbers the cells type by type.
    integer, parameter :: N_MED_TYPES = 24
    integer(i4), parameter :: MED_TYPE_CODES(N_MED_TYPES) = [1, 102, 103, 203, 206, 204, &
        208, 209, 104, 207, 304, 305, 306, 308, 310, 312, 313, 315, 318, 320, 327, 400, 420, 500]
    character(len=10), parameter :: MED_TYPE_NAMES(N_MED_TYPES) = [character(len=10) :: &
        'POI1', 'SEG2', 'SEG3', 'TRIA3', 'TRIA6', 'QUAD4', 'QUAD8', 'QUAD9', 'SEG4', 'TRIA7', &
        'TETRA4', 'PYRAM5', 'PENTA6', 'HEXA8', 'TETRA10', 'OCTA12', 'PYRAM13', 'PENTA15', &
        'PENTA18', 'HEXA20', 'HEXA27', 'POLYGON', 'QPOLYGON', 'POLYHEDRON']
    integer, parameter :: N_READ_TYPES = 8
    integer(i4), parameter :: READ_TYPE_CELL(N_READ_TYPES) = CELL_TYPE_ORDER
    integer(i4), parameter :: READ_TYPE_NODES(N_READ_TYPES) = CELL_TYPE_NODES(CELL_TYPE_ORDER)
    !> The types read, for messages.
    character(len=*), parameter :: READ_TYPES_TEXT = &
        'POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8 and QUAD9'

    !> A family of the file: its number and groups.
    type :: family_t
        integer(i4) :: number = 0
        character(len=:), allocatable :: name
        type(string_t), allocatable :: groups(:)
        integer(i4), allocatable :: group_ids(:)   !< into the node or cell group registry
    end type family_t

    public :: read_med_mesh, med_type_name

contains

    !> Reads a mesh from a MED file (see the module header).
    !>  path      : in, the MED file
    !>  mesh      : out, the mesh (mesh%file = path)
    !>  st        : out, errors, each message starting with "MED file PATH:" (no file, not
    !>              MED, unreadable version, damaged contents, inconsistent counts, unknown
    !>              cell types, several meshes and no name, no mesh of that name), with
    !>              st%keyword = 'NOM_MED' when the mesh name is at fault
    !>  mesh_name : in, optional, NOM_MED ('' or absent: the file's only mesh)
    !>  notes     : out, optional, lines for the .mess (mesh read, groups dropped)
    subroutine read_med_mesh(path, mesh, st, mesh_name, notes)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: mesh_name
        type(string_t), allocatable, intent(out), optional :: notes(:)
        type(med_file_t) :: file
        type(string_t), allocatable :: lines(:)
        character(len=:), allocatable :: wanted, prefix
        allocate (lines(0))
        if (present(notes)) allocate (notes(0))
        wanted = ''
        if (present(mesh_name)) wanted = trim(mesh_name)
        call med_load(st)   ! its errors are about parasol's install, not about the file
        if (st%failed()) return
        call med_open(file, path, MED_READ, st)
        if (st%ok()) then
            if (len(file%converted_from) > 0) then
                lines = [lines, string_t('MED file ' // path // ' was written by MED ' // &
                    file%converted_from // ': read from a copy converted to MED ' // &
                    file%converted_to // ' by the MED library''s MEDimport (a temporary ' // &
                    'file, removed after)')]
            end if
            call read_open_file(file, wanted, mesh, lines, st)
        end if
        call med_close(file)
        if (st%failed()) then
            prefix = 'MED file ' // path
            if (.not. starts_with(st%message, prefix) .and. &
                .not. starts_with(st%message, path)) st%message = prefix // ': ' // st%message
            if (allocated(st%file)) deallocate (st%file)
            st%line = 0
        end if
        if (present(notes)) call move_alloc(lines, notes)
    end subroutine read_med_mesh

    ! The steps of read_med_mesh on an open file.
    subroutine read_open_file(file, wanted, mesh, notes, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: wanted
        type(mesh_t), intent(inout) :: mesh
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name
        integer(i4) :: spacedim, numdt, numit, n_nodes
        real(dp), allocatable :: coords(:, :)
        integer(i4), allocatable :: node_family(:), cell_family(:), cell_kind(:), &
            cell_nodes(:, :)
        character(len=MED_SNAME_LEN), allocatable :: node_names(:), cell_names(:)
        logical :: node_named
        logical, allocatable :: cell_named(:)
        type(family_t), allocatable :: families(:)
        call choose_mesh(file, wanted, name, spacedim, numdt, numit, st)
        if (st%failed()) return
        call read_nodes(file, name, spacedim, numdt, numit, coords, node_names, node_named, &
                        node_family, st)
        if (st%failed()) return
        n_nodes = size(coords, 2, kind=i4)
        call read_cells(file, name, numdt, numit, n_nodes, cell_kind, cell_nodes, cell_names, &
                        cell_named, cell_family, st)
        if (st%failed()) return
        call read_families(file, name, families, st)
        if (st%failed()) return
        call build_mesh(file, spacedim, coords, cell_kind, cell_nodes, mesh, st)
        if (st%failed()) return
        call add_groups(file, families, node_family, cell_family, mesh, notes, st)
        if (st%failed()) return
        call mesh_finish(mesh, 0_i4, st)
        if (st%failed()) return
        call add_note(notes, 'MED mesh ' // name // ' (space dimension ' // &
            to_text(spacedim) // ')')
    end subroutine read_open_file

    ! The mesh to read: NOM_MED, or the only one; its dimension and first computation step.
    subroutine choose_mesh(file, wanted, name, spacedim, numdt, numit, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: wanted
        character(len=:), allocatable, intent(out) :: name
        integer(i4), intent(out) :: spacedim, numdt, numit
        type(status_t), intent(out) :: st
        integer(i4) :: n_meshes, it, chosen, nstep, sd, steps
        logical :: structured, grid
        character(len=:), allocatable :: this, listed
        type(string_t), allocatable :: names(:)
        n_meshes = med_mesh_count(file, st)
        if (st%failed()) return
        if (n_meshes == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ' holds no mesh')
            return
        end if
        allocate (names(n_meshes))
        chosen = 0
        spacedim = 0
        nstep = 0
        structured = .false.
        do it = 1, n_meshes
            call med_mesh_info(file, it, this, sd, grid, steps, st)
            if (st%failed()) return
            names(it)%s = this
            if ((len(wanted) == 0 .and. n_meshes == 1) .or. &
                (len(wanted) > 0 .and. this == wanted .and. chosen == 0)) then
                chosen = it
                spacedim = sd
                structured = grid
                nstep = steps
            end if
        end do
        listed = names(1)%s
        do it = 2, n_meshes
            listed = listed // ', ' // names(it)%s
        end do
        if (chosen == 0) then
            if (len(wanted) == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ' holds ' // &
                    to_text(n_meshes) // ' meshes (' // listed // '): name the one to read ' // &
                    'with NOM_MED', keyword='NOM_MED')
            else
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ' has no ' // &
                    'mesh named ' // wanted // ' (it holds: ' // listed // ')', &
                    keyword='NOM_MED')
            end if
            return
        end if
        name = names(chosen)%s
        if (structured) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                name // ' is a structured grid; parasol reads unstructured meshes')
            return
        end if
        if (spacedim /= 2 .and. spacedim /= 3) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                name // ' has space dimension ' // to_text(spacedim) // '; parasol reads ' // &
                'meshes of dimension 2 (D_PLAN, 2D_DIS_T) and 3 (DKT, DIS_T)')
            return
        end if
        if (nstep < 1) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                name // ' has no computation step, hence no nodes')
            return
        end if
        call med_mesh_step(file, name, 1_i4, numdt, numit, st)   ! the first, as Code_Aster
    end subroutine choose_mesh

    ! Coordinates (3, n) (z = 0 in 2D), names and family numbers of the nodes.
    subroutine read_nodes(file, mesh, spacedim, numdt, numit, coords, names, named, &
                          families, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: spacedim, numdt, numit
        real(dp), allocatable, intent(out) :: coords(:, :)
        character(len=MED_SNAME_LEN), allocatable, intent(out) :: names(:)
        logical, intent(out) :: named
        integer(i4), allocatable, intent(out) :: families(:)
        type(status_t), intent(out) :: st
        integer(i4) :: n, n_names, n_families, k
        real(dp), allocatable :: flat(:)
        integer :: ios
        named = .false.
        n = med_count(file, mesh, numdt, numit, MED_COUNT_NODES, 0_i4, 'nodes', st)
        if (st%failed()) return
        if (n == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                mesh // ' has no nodes')
            return
        end if
        if (int(n, i8) * spacedim > huge(1_i4)) then
            call too_many(st, file, n, 'nodes')
            return
        end if
        allocate (flat(spacedim * n), coords(3, n), families(n), stat=ios)
        if (ios /= 0) then
            call too_many(st, file, n, 'nodes')
            return
        end if
        call med_read_coordinates(file, mesh, numdt, numit, flat, st)
        if (st%failed()) return
        coords = 0.0_dp
        coords(1:spacedim, :) = reshape(flat, [spacedim, n])
        do k = 1, n
            if (.not. all(ieee_is_finite(coords(:, k)))) then
                call bad_coordinate(st, file, k)
                return
            end if
        end do
        n_names = med_count(file, mesh, numdt, numit, MED_COUNT_NODE_NAMES, 0_i4, &
                            'node names', st)
        if (st%failed()) return
        allocate (names(n))
        if (n_names > 0) then
            call check_same(st, file, n_names, 'names', n, 'nodes')
            if (st%failed()) return
            call med_read_names(file, mesh, numdt, numit, MED_NODES, 0_i4, n, names, 'nodes', st)
            if (st%failed()) return
            named = .true.
        end if
        families = 0
        n_families = med_count(file, mesh, numdt, numit, MED_COUNT_NODE_FAMILIES, 0_i4, &
                               'node family numbers', st)
        if (st%failed()) return
        if (n_families > 0) then
            call check_same(st, file, n_families, 'family numbers', n, 'nodes')
            if (st%failed()) return
            call med_read_families(file, mesh, numdt, numit, MED_NODES, 0_i4, families, &
                                   'nodes', st)
        end if
    end subroutine read_nodes

    ! The cells, all types together in Code_Aster's order: type (index into READ_TYPE_*),
    ! nodes (MAX_CELL_NODES, n; unused entries 0), names and family numbers.
    subroutine read_cells(file, mesh, numdt, numit, n_nodes, kinds_, nodes, names, named, &
                          families, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        integer(i4), intent(in) :: numdt, numit, n_nodes
        integer(i4), allocatable, intent(out) :: kinds_(:), nodes(:, :), families(:)
        character(len=MED_SNAME_LEN), allocatable, intent(out) :: names(:)
        logical, allocatable, intent(out) :: named(:)
        type(status_t), intent(out) :: st
        integer(i4) :: counts(N_READ_TYPES), all_counts(N_MED_TYPES)
        integer(i4) :: n_types, t, n, total, first, c, k, np, code
        integer(i4) :: n_names, n_families
        integer(i4), allocatable :: conn(:)
        integer :: ios
        n_types = med_count(file, mesh, numdt, numit, MED_COUNT_CELL_TYPES, 0_i4, &
                            'cell types', st)
        if (st%failed()) return
        all_counts = 0
        do k = 1, n_types
            call med_cell_type(file, mesh, numdt, numit, k, code, st)
            if (st%failed()) return
            t = findloc(MED_TYPE_CODES, code, dim=1)
            if (t == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                    mesh // ' has cells of MED type ' // to_text(code) // ', which parasol ' &
                    // 'does not know (structural elements?); it reads ' // READ_TYPES_TEXT)
                return
            end if
            n = med_count(file, mesh, numdt, numit, MED_COUNT_CELLS, code, &
                          trim(MED_TYPE_NAMES(t)) // ' cells', st)
            if (st%failed()) return
            if (n == 0) then
                n = med_count(file, mesh, numdt, numit, MED_COUNT_DESCENDING_CELLS, code, &
                              trim(MED_TYPE_NAMES(t)) // ' cells', st)
                if (st%failed()) return
                if (n == 0) cycle
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' &
                    // mesh // ' gives its ' // trim(MED_TYPE_NAMES(t)) // ' cells by ' // &
                    'descending connectivity (faces and edges); parasol reads nodal ' // &
                    'connectivity, as Code_Aster')
                return
            end if
            if (t > N_READ_TYPES) then
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': mesh ' // &
                    mesh // ' has ' // to_text(n) // ' ' // trim(MED_TYPE_NAMES(t)) // &
                    ' cells (MED type ' // to_text(code) // '); parasol reads ' // &
                    READ_TYPES_TEXT // ' cells only')
                return
            end if
            all_counts(t) = n
        end do
        counts = all_counts(1:N_READ_TYPES)
        if (sum(int(counts, i8) * MAX_CELL_NODES) > huge(1_i4)) then
            call too_many(st, file, sum(int(counts, i8)), 'cells')
            return
        end if
        total = sum(counts)
        allocate (kinds_(total), nodes(MAX_CELL_NODES, total), names(total), named(total), &
                  families(total), stat=ios)
        if (ios /= 0) then
            call too_many(st, file, total, 'cells')
            return
        end if
        nodes = 0
        families = 0
        named = .false.
        first = 0
        do t = 1, N_READ_TYPES
            n = counts(t)
            if (n == 0) cycle
            np = READ_TYPE_NODES(t)
            allocate (conn(np * n), stat=ios)
            if (ios /= 0) then
                call too_many(st, file, n, trim(MED_TYPE_NAMES(t)) // ' cells')
                return
            end if
            call med_read_connectivity(file, mesh, numdt, numit, MED_TYPE_CODES(t), conn, &
                                       trim(MED_TYPE_NAMES(t)), st)
            if (st%failed()) return
            do c = 1, n
                kinds_(first + c) = t
                nodes(1:np, first + c) = conn((c - 1) * np + 1:c * np)
                do k = 1, np
                    if (nodes(k, first + c) < 1 .or. nodes(k, first + c) > n_nodes) then
                        call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // &
                            ': ' // trim(MED_TYPE_NAMES(t)) // ' cell ' // to_text(c) // &
                            ' (cell M' // to_text(first + c) // ') refers to node ' // &
                            to_text(nodes(k, first + c)) // ', but mesh ' // mesh // &
                            ' has nodes 1 to ' // to_text(n_nodes))
                        return
                    end if
                end do
            end do
            deallocate (conn)
            n_names = med_count(file, mesh, numdt, numit, MED_COUNT_CELL_NAMES, &
                                MED_TYPE_CODES(t), trim(MED_TYPE_NAMES(t)) // ' names', st)
            if (st%failed()) return
            if (n_names > 0) then
                call check_same(st, file, n_names, 'names', n, trim(MED_TYPE_NAMES(t)) // &
                                ' cells')
                if (st%failed()) return
                call med_read_names(file, mesh, numdt, numit, MED_CELLS, MED_TYPE_CODES(t), n, &
                                    names(first + 1:first + n), trim(MED_TYPE_NAMES(t)) // &
                                    ' cells', st)
                if (st%failed()) return
                named(first + 1:first + n) = .true.
            end if
            n_families = med_count(file, mesh, numdt, numit, MED_COUNT_CELL_FAMILIES, &
                                   MED_TYPE_CODES(t), trim(MED_TYPE_NAMES(t)) // &
                                   ' family numbers', st)
            if (st%failed()) return
            if (n_families > 0) then
                call check_same(st, file, n_families, 'family numbers', n, &
                                trim(MED_TYPE_NAMES(t)) // ' cells')
                if (st%failed()) return
                call med_read_families(file, mesh, numdt, numit, MED_CELLS, MED_TYPE_CODES(t), &
                                       families(first + 1:first + n), &
                                       trim(MED_TYPE_NAMES(t)) // ' cells', st)
                if (st%failed()) return
            end if
            first = first + n
        end do
    end subroutine read_cells

    ! Every family of the mesh: number and group names.
    subroutine read_families(file, mesh, families, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: mesh
        type(family_t), allocatable, intent(out) :: families(:)
        type(status_t), intent(out) :: st
        integer(i4) :: n, it, n_groups, g, j
        integer(i4), allocatable :: keys(:), order(:)
        character(len=MED_LNAME_LEN), allocatable :: groups(:)
        character(len=:), allocatable :: name
        integer :: ios
        n = med_family_count(file, mesh, st)
        if (st%failed()) return
        allocate (families(n), stat=ios)
        if (ios /= 0) then
            call too_many(st, file, n, 'families')
            return
        end if
        do it = 1, n
            n_groups = med_family_group_count(file, mesh, it, st)
            if (st%failed()) return
            if (n_groups > MAX_GROUPS_PER_FAMILY) then
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': family ' &
                    // to_text(it) // ' of mesh ' // mesh // ' claims ' // to_text(n_groups) &
                    // ' groups (at most ' // to_text(MAX_GROUPS_PER_FAMILY) // ' expected)')
                return
            end if
            allocate (groups(n_groups))
            call med_family_info(file, mesh, it, name, families(it)%number, groups, st)
            if (st%failed()) return
            families(it)%name = name
            allocate (families(it)%groups(n_groups), families(it)%group_ids(n_groups))
            families(it)%group_ids = 0
            do g = 1, n_groups
                families(it)%groups(g)%s = trim(groups(g))
                if (len(families(it)%groups(g)%s) == 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // &
                        ': family ' // name // ' of mesh ' // mesh // ' has a group with ' // &
                        'an empty name')
                    return
                end if
            end do
            deallocate (groups)
        end do
        call sort_family_numbers(families, keys, order)
        do j = 1, n - 1
            if (keys(j) == keys(j + 1)) then
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // &
                    ': families ' // families(order(j))%name // ' and ' // &
                    families(order(j + 1))%name // ' of mesh ' // mesh // &
                    ' have the same number ' // to_text(keys(j)))
                return
            end if
        end do
    end subroutine read_families

    ! Nodes and cells into the mesh, named as Code_Aster names them.
    subroutine build_mesh(file, spacedim, coords, cell_kind, cell_nodes, mesh, st)
        type(med_file_t), intent(in) :: file
        integer(i4), intent(in) :: spacedim
        real(dp), intent(in) :: coords(:, :)
        integer(i4), intent(in) :: cell_kind(:), cell_nodes(:, :)
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: k, t
        character(len=:), allocatable :: name
        call mesh_init(mesh, spacedim, file%path)
        ! the file's names are not Code_Aster's (module header): numbers name the entities
        do k = 1, size(coords, 2, kind=i4)
            name = number_name('N', k)
            call mesh_add_node(mesh, name, coords(:, k), 0_i4, st)
            if (st%failed()) return
        end do
        do k = 1, size(cell_kind, kind=i4)
            t = cell_kind(k)
            name = number_name('M', k)
            call mesh_add_cell(mesh, name, READ_TYPE_CELL(t), &
                               cell_nodes(1:READ_TYPE_NODES(t), k), 0_i4, st)
            if (st%failed()) return
        end do
    end subroutine build_mesh

    ! GROUP_NO and GROUP_MA from the families (see the module header).
    subroutine add_groups(file, families, node_family, cell_family, mesh, notes, st)
        type(med_file_t), intent(in) :: file
        type(family_t), intent(inout) :: families(:)
        integer(i4), intent(in) :: node_family(:), cell_family(:)
        type(mesh_t), intent(inout) :: mesh
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(out) :: st
        type(name_index_t) :: node_groups, cell_groups
        integer(i4) :: f, g, id
        integer(i4), allocatable :: node_ptr(:), node_items(:), cell_ptr(:), cell_items(:)
        ! Registration order: families in file order, groups in family order (MeshReader).
        do f = 1, size(families)
            do g = 1, size(families(f)%groups)
                if (families(f)%number > 0) then
                    call name_add(node_groups, families(f)%groups(g)%s, id)
                else
                    call name_add(cell_groups, families(f)%groups(g)%s, id)
                end if
                families(f)%group_ids(g) = abs(id)
            end do
        end do
        call collect_members(file, families, node_family, node_groups%count, .true., &
                             mesh, node_ptr, node_items, st)
        if (st%failed()) return
        call collect_members(file, families, cell_family, cell_groups%count, .false., &
                             mesh, cell_ptr, cell_items, st)
        if (st%failed()) return
        call register_groups(node_groups, node_ptr, node_items, .true., mesh, notes, st)
        if (st%failed()) return
        call register_groups(cell_groups, cell_ptr, cell_items, .false., mesh, notes, st)
    end subroutine add_groups

    ! Members of each group in CSR form: group g holds items(ptr(g):ptr(g+1)-1). Entities are
    ! visited in increasing order, so each group's members come sorted.
    subroutine collect_members(file, families, entity_family, n_groups, nodes, mesh, ptr, &
                               items, st)
        type(med_file_t), intent(in) :: file
        type(family_t), intent(in) :: families(:)
        integer(i4), intent(in) :: entity_family(:), n_groups
        logical, intent(in) :: nodes
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: ptr(:), items(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: fill(:), family_index(:), keys(:), order(:)
        integer(i4) :: e, f, g, number
        character(len=:), allocatable :: what, why
        allocate (family_index(size(entity_family)), ptr(n_groups + 1))
        call sort_family_numbers(families, keys, order)
        ptr = 0
        what = 'cell '
        if (nodes) what = 'node '
        do e = 1, size(entity_family, kind=i4)
            family_index(e) = 0
            number = entity_family(e)
            if (number == 0) cycle
            f = find_family(keys, order, number)
            if (f == 0 .or. (nodes .neqv. number > 0)) then
                why = 'which the file does not define'
                if (f /= 0) why = 'a family of the wrong kind (MED numbers node families ' // &
                    '> 0, cell families < 0)'
                call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': ' // &
                    what // entity_name(mesh, nodes, e) // ' belongs to family ' // &
                    to_text(number) // ', ' // why)
                return
            end if
            family_index(e) = f
            do g = 1, size(families(f)%group_ids)
                ptr(families(f)%group_ids(g) + 1) = ptr(families(f)%group_ids(g) + 1) + 1
            end do
        end do
        ptr(1) = 1
        do g = 1, n_groups
            ptr(g + 1) = ptr(g) + ptr(g + 1)
        end do
        allocate (items(ptr(n_groups + 1) - 1), fill(n_groups))
        fill = ptr(1:n_groups)
        do e = 1, size(entity_family, kind=i4)
            f = family_index(e)
            if (f == 0) cycle
            do g = 1, size(families(f)%group_ids)
                items(fill(families(f)%group_ids(g))) = e
                fill(families(f)%group_ids(g)) = fill(families(f)%group_ids(g)) + 1
            end do
        end do
    end subroutine collect_members

    ! Adds the non-empty groups whose names Code_Aster keeps; notes the others.
    subroutine register_groups(names, ptr, items, nodes, mesh, notes, st)
        type(name_index_t), intent(in) :: names
        integer(i4), intent(in) :: ptr(:), items(:)
        logical, intent(in) :: nodes
        type(mesh_t), intent(inout) :: mesh
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(out) :: st
        integer(i4) :: g, first, last
        character(len=:), allocatable :: name
        do g = 1, names%count
            first = ptr(g)
            last = ptr(g + 1) - 1
            if (last < first) cycle                      ! empty groups are dropped
            name = name_of(names, g)
            if (len(name) > MED_GROUP_NAME_MAX) then
                call add_note(notes, 'group ' // name // ' ignored: its name has more than ' &
                    // to_text(int(MED_GROUP_NAME_MAX, i4)) // ' characters (Code_Aster''s ' &
                    // 'limit)')
                cycle
            end if
            if (nodes) then
                call mesh_add_node_group(mesh, name, items(first:last), 0_i4, st)
            else
                call mesh_add_cell_group(mesh, name, items(first:last), 0_i4, st)
            end if
            if (st%failed()) return
        end do
    end subroutine register_groups

    ! The family numbers in increasing order (keys) and the family each comes from (order),
    ! for find_family: O(log n) per entity, whatever the numbers (a bottom-up merge sort).
    pure subroutine sort_family_numbers(families, keys, order)
        type(family_t), intent(in) :: families(:)
        integer(i4), allocatable, intent(out) :: keys(:), order(:)
        integer(i4), allocatable :: next(:)
        integer(i4) :: n, width, lo, mid, hi, i, j, k
        logical :: take_left
        n = size(families, kind=i4)
        allocate (order(n), next(n))
        order = [(i, i = 1_i4, n)]
        width = 1
        do while (width < n)
            do lo = 1, n, 2 * width
                mid = min(lo + width, n + 1)
                hi = min(lo + 2 * width, n + 1)
                i = lo
                j = mid
                do k = lo, hi - 1
                    take_left = j >= hi             ! Fortran does not short-circuit: nest
                    if (i < mid .and. .not. take_left) take_left = number_of(i) <= number_of(j)
                    if (i >= mid) take_left = .false.
                    if (take_left) then
                        next(k) = order(i)
                        i = i + 1
                    else
                        next(k) = order(j)
                        j = j + 1
                    end if
                end do
            end do
            order = next
            width = 2 * width
        end do
        allocate (keys(n))
        do i = 1, n
            keys(i) = families(order(i))%number
        end do
    contains
        pure integer(i4) function number_of(position)
            integer(i4), intent(in) :: position
            number_of = families(order(position))%number
        end function number_of
    end subroutine sort_family_numbers

    ! prefix // decimal number (>= 1), without an internal write: every unnamed node and cell
    ! gets one, and a formatted write per name would dominate the reading time.
    pure function number_name(prefix, number) result(name)
        character, intent(in) :: prefix
        integer(i4), intent(in) :: number
        character(len=:), allocatable :: name
        character(len=11) :: digits
        integer(i4) :: value, k
        value = number
        k = len(digits) + 1
        do
            k = k - 1
            digits(k:k) = achar(48 + mod(value, 10))
            value = value / 10
            if (value == 0) exit
        end do
        name = prefix // digits(k:)
    end function number_name

    ! Index of the family numbered `number` (keys, order from sort_family_numbers), 0 if none.
    pure integer(i4) function find_family(keys, order, number) result(index)
        integer(i4), intent(in) :: keys(:), order(:), number
        integer(i4) :: lo, hi, mid
        index = 0
        lo = 1
        hi = size(keys, kind=i4)
        do while (lo <= hi)
            mid = lo + (hi - lo) / 2
            if (keys(mid) == number) then
                index = order(mid)
                return
            else if (keys(mid) < number) then
                lo = mid + 1
            else
                hi = mid - 1
            end if
        end do
    end function find_family

    ! Name of node or cell e of the mesh being built.
    function entity_name(mesh, nodes, e) result(name)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: nodes
        integer(i4), intent(in) :: e
        character(len=:), allocatable :: name
        if (nodes) then
            name = name_of(mesh%node_names, e)
        else
            name = name_of(mesh%cell_names, e)
        end if
    end function entity_name

    !> Code_Aster name of a MED cell type code ('' if unknown).
    pure function med_type_name(code) result(name)
        integer(i4), intent(in) :: code
        character(len=:), allocatable :: name
        integer :: t
        name = ''
        do t = 1, N_MED_TYPES
            if (MED_TYPE_CODES(t) == code) name = trim(MED_TYPE_NAMES(t))
        end do
    end function med_type_name

    ! "the file gives 3 names for 64 QUAD4 cells".
    subroutine check_same(st, file, n_given, given, n, what)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        integer(i4), intent(in) :: n_given, n
        character(len=*), intent(in) :: given, what
        if (n_given == n) return
        call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': it gives ' // &
            to_text(n_given) // ' ' // given // ' for ' // to_text(n) // ' ' // what // &
            ' (the counts must be equal)')
    end subroutine check_same

    subroutine too_many(st, file, n, what)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        class(*), intent(in) :: n
        character(len=*), intent(in) :: what
        character(len=:), allocatable :: count
        select type (n)
        type is (integer(i4))
            count = to_text(n)
        type is (integer(i8))
            count = to_text(n)
        class default
            count = 'so many'
        end select
        call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': it claims ' // &
            count // ' ' // what // ', more than this machine can hold')
    end subroutine too_many

    subroutine bad_coordinate(st, file, k)
        type(status_t), intent(inout) :: st
        type(med_file_t), intent(in) :: file
        integer(i4), intent(in) :: k
        call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': node ' // &
            to_text(k) // ' has a coordinate that is not a finite number')
    end subroutine bad_coordinate

    subroutine add_note(notes, line)
        type(string_t), allocatable, intent(inout) :: notes(:)
        character(len=*), intent(in) :: line
        type(string_t), allocatable :: bigger(:)
        allocate (bigger(size(notes) + 1))
        bigger(1:size(notes)) = notes
        bigger(size(bigger))%s = line
        call move_alloc(bigger, notes)
    end subroutine add_note

end module mesh_med_reader
