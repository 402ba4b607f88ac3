!> Reading the keywords the DEFI_GROUP options share (U4.22.01), with errors at the keyword
!> as Code_Aster raises them (utcono, the cgma*/cgno* routines): the centre (POINT,
!> NOEUD_CENTRE, GROUP_NO_CENTRE), a direction (VECT_NORMALE or ANGL_NAUT), a positive
!> length (RAYON, DIST, PRECISION), named cells and nodes (MAILLE, NOEUD: a name given twice
!> is an alarm), a slice of a group (NUME_INIT, NUME_FIN, POSITION); and the .mess report
!> of a group made.
module mesh_group_keywords
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: string_t, to_text
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell, find_node, cell_name, node_name, cells_of_group, &
        nodes_of_group
    use mesh_geometry, only: nautical_direction, normalized
    use mesh_group_select, only: first_occurrences, ordered_union, ordered_intersection, &
        ordered_difference
    use mesh_command_support, only: relocate_error, warn_at, group_first_node, read_groups, &
        read_node_groups
    implicit none
    private

    !> How many values a direction takes (read_direction's `policy`):
    !>  DIRECTION_AT_LEAST: at least ndim components / ndim-1 angles, the extra ones ignored
    !>                      (FACE_NORMALE, cgmafn);
    !>  DIRECTION_EXACT: exactly ndim components / at least ndim-1 angles (BANDE, PLAN);
    !>  DIRECTION_3D: a 3D mesh only, exactly 3 components / 2 angles (CYLINDRE,
    !>                ENV_CYLINDRE).
    integer, parameter, public :: DIRECTION_AT_LEAST = 1, DIRECTION_EXACT = 2, &
        DIRECTION_3D = 3

    public :: read_centre, read_direction, read_positive, read_named_cells, &
        read_named_nodes, group_slice, report_group, fold_groups, first_group_slice

contains

    !> The centre of a geometric option: POINT (exactly ndim coordinates), NOEUD_CENTRE or
    !> the first node of GROUP_NO_CENTRE; z = 0 when ndim = 2.
    subroutine read_centre(ctx, occ, mesh, ndim, x0, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: ndim
        real(dp), intent(out) :: x0(3)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: point(:)
        character(len=:), allocatable :: name
        integer(i4) :: node
        x0 = 0.0_dp
        if (occ%has('POINT')) then
            call occ%get_reals('POINT', point, st)
            if (st%failed()) return
            if (size(point) /= ndim) then
                call occ%error_at('POINT', 'expected ' // to_text(ndim) // ' coordinates ' // &
                    'for a mesh of dimension ' // to_text(ndim) // ', got ' // &
                    to_text(size(point, kind=i4)), st)
                return
            end if
            x0(1:ndim) = point
            return
        end if
        if (occ%has('NOEUD_CENTRE')) then
            call occ%get_text('NOEUD_CENTRE', name, st)
            if (st%failed()) return
            node = find_node(mesh, name, st)
            if (st%failed()) then
                call relocate_error(occ, 'NOEUD_CENTRE', st)
                return
            end if
        else
            call group_first_node(ctx, occ, 'GROUP_NO_CENTRE', mesh, node, st)
            if (st%failed()) return
        end if
        x0(1:ndim) = mesh%coords(1:ndim, node)
    end subroutine read_centre

    !> The unit direction of VECT_NORMALE or ANGL_NAUT (degrees) for a mesh of dimension
    !> `ndim`, with the value counts of `policy`. Errors at the keyword: a wrong count, a zero
    !> vector, a 2D mesh where a 3D one is needed (`key_3d`, the option named).
    subroutine read_direction(occ, ndim, policy, option, v, st)
        type(keyword_set_t), intent(in) :: occ
        integer(i4), intent(in) :: ndim
        integer, intent(in) :: policy
        character(len=*), intent(in) :: option
        real(dp), intent(out) :: v(3)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: values(:)
        real(dp) :: raw(3)
        logical :: ok
        integer(i4) :: need
        v = 0.0_dp
        if (policy == DIRECTION_3D .and. ndim /= 3) then
            call occ%error_at('OPTION', 'OPTION=''' // option // ''' needs a 3D mesh (the ' // &
                'nodes of this mesh all have the same z: it is plane)', st)
            return
        end if
        if (occ%has('ANGL_NAUT')) then
            call occ%get_reals('ANGL_NAUT', values, st)
            if (st%failed()) return
            need = ndim - 1
            if (size(values) < need .or. (policy == DIRECTION_3D .and. size(values) /= 2)) then
                call occ%error_at('ANGL_NAUT', 'expected ' // to_text(need) // ' angle(s) ' // &
                    'for a mesh of dimension ' // to_text(ndim) // ', got ' // &
                    to_text(size(values, kind=i4)), st)
                return
            end if
            v = nautical_direction(values(1:need), ndim)
            return
        end if
        call occ%get_reals('VECT_NORMALE', values, st)
        if (st%failed()) return
        if (size(values) < ndim .or. (policy /= DIRECTION_AT_LEAST .and. &
                                      size(values) /= ndim)) then
            call occ%error_at('VECT_NORMALE', 'expected ' // to_text(ndim) // ' components ' // &
                'for a mesh of dimension ' // to_text(ndim) // ', got ' // &
                to_text(size(values, kind=i4)), st)
            return
        end if
        raw = 0.0_dp
        raw(1:ndim) = values(1:ndim)
        call normalized(raw, v, ok)
        if (.not. ok) call occ%error_at('VECT_NORMALE', 'the vector is zero (a direction ' // &
                                        'is needed)', st)
    end subroutine read_direction

    !> A length that must be > 0 (RAYON, DIST, PRECISION: Code_Aster refuses 0 and less).
    subroutine read_positive(occ, key, x, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        real(dp), intent(out) :: x
        type(status_t), intent(out) :: st
        call occ%get_real(key, x, st)
        if (st%failed()) return
        if (.not. (x > 0.0_dp)) call occ%error_at(key, 'must be positive (got ' // &
                                                  to_text(x) // ')', st)
    end subroutine read_positive

    !> The cells named by keyword `key` (MAILLE), in the order given; a cell named twice is
    !> kept once with a warning naming the group being made (SOUSTRUC_32).
    !>  quiet : optional, no warning for a cell named twice (selections that are sets)
    subroutine read_named_cells(ctx, occ, key, mesh, group, cells, st, quiet)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, group
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: quiet
        call read_named(ctx, occ, key, mesh, group, .true., cells, st, quiet)
    end subroutine read_named_cells

    !> The nodes named by keyword `key` (NOEUD), as read_named_cells (SOUSTRUC_39).
    subroutine read_named_nodes(ctx, occ, key, mesh, group, nodes, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, group
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        call read_named(ctx, occ, key, mesh, group, .false., nodes, st)
    end subroutine read_named_nodes

    ! Named cells (cells) or nodes, each kept once.
    subroutine read_named(ctx, occ, key, mesh, group, cells, numbers, st, quiet)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, group
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: cells
        integer(i4), allocatable, intent(out) :: numbers(:)
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: quiet
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: given(:), repeated(:)
        integer(i4) :: i
        call occ%get_texts(key, names, st)
        if (st%failed()) return
        allocate (given(size(names)))
        do i = 1, size(names, kind=i4)
            if (cells) then
                given(i) = find_cell(mesh, names(i)%s, st)
            else
                given(i) = find_node(mesh, names(i)%s, st)
            end if
            if (st%failed()) then
                call relocate_error(occ, key, st)
                return
            end if
        end do
        call first_occurrences(given, merge(mesh%n_cells, mesh%n_nodes, cells), numbers, &
                               repeated)
        if (present(quiet)) then
            if (quiet) return
        end if
        do i = 1, size(repeated, kind=i4)
            call warn_at(ctx, occ, key, trim(merge('cell', 'node', cells)) // ' ' // &
                names(repeated(i))%s // ' is given twice for ' // group // ': it is kept once')
        end do
    end subroutine read_named

    !> The members of the groups named by keyword `key` (cell groups when `cells`, else node
    !> groups of `mesh`), folded from the first group by `operation`: 'UNION' (the first's
    !> members, then the others' new ones), 'INTERSEC' or 'DIFFE' (the first's order), as
    !> Code_Aster's utlisi.
    !>  st : out, a group missing in the mesh, at `key`
    subroutine fold_groups(occ, key, mesh, cells, operation, members, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, operation
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: cells
        integer(i4), allocatable, intent(out) :: members(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), other(:)
        integer(i4) :: g, n
        if (cells) then
            call read_groups(occ, key, mesh, names, groups, st)
            n = mesh%n_cells
        else
            call read_node_groups(occ, key, mesh, names, groups, st)
            n = mesh%n_nodes
        end if
        if (st%failed()) return
        members = group_members(groups(1))
        do g = 2, size(groups, kind=i4)
            other = group_members(groups(g))
            select case (operation)
            case ('INTERSEC')
                members = ordered_intersection(members, other, n)
            case ('DIFFE')
                members = ordered_difference(members, other, n)
            case default
                members = ordered_union(members, other, n)
            end select
        end do
    contains
        function group_members(g) result(list)
            integer(i4), intent(in) :: g
            integer(i4), allocatable :: list(:)
            if (cells) then
                list = cells_of_group(mesh, g)
            else
                list = nodes_of_group(mesh, g)
            end if
        end function group_members
    end subroutine fold_groups

    !> GROUP_MA / GROUP_NO of a group made from a slice of another: the first group given
    !> (Code_Aster's sscgma / sscgno read only the first; more are pointed out, not used),
    !> sliced by group_slice. `cells`: cell groups, else node groups.
    subroutine first_group_slice(ctx, occ, key, mesh, cells, members, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: cells
        integer(i4), allocatable, intent(out) :: members(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:)
        if (cells) then
            call read_groups(occ, key, mesh, names, groups, st)
        else
            call read_node_groups(occ, key, mesh, names, groups, st)
        end if
        if (st%failed()) return
        if (size(groups) > 1) call warn_at(ctx, occ, key, 'only the first group, ' // &
            names(1)%s // ', is used (as in Code_Aster; combine groups with UNION)')
        if (cells) then
            call group_slice(occ, key, cells_of_group(mesh, groups(1)), members, st)
        else
            call group_slice(occ, key, nodes_of_group(mesh, groups(1)), members, st)
        end if
    end subroutine first_group_slice

    !> The part of a group's members that NUME_INIT / NUME_FIN (default: the whole group) or
    !> POSITION (INIT: the first, FIN: the last, MILIEU: member (n+1)/2) choose.
    !>  key : the keyword naming the group (GROUP_MA, GROUP_NO), for messages
    !>  st  : out, NUME_FIN before NUME_INIT, NUME_FIN beyond the group, an empty group
    subroutine group_slice(occ, key, members, part, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        integer(i4), intent(in) :: members(:)
        integer(i4), allocatable, intent(out) :: part(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: position
        integer(i4) :: first, last, n
        n = size(members, kind=i4)
        if (occ%has('POSITION')) then
            call occ%get_text('POSITION', position, st)
            if (st%failed()) return
            if (n == 0) then
                call occ%error_at(key, 'the group is empty (POSITION needs a member)', st)
                return
            end if
            select case (position)
            case ('INIT')
                part = members(1:1)
            case ('FIN')
                part = members(n:n)
            case default
                part = members((n + 1) / 2:(n + 1) / 2)
            end select
            return
        end if
        first = 1
        last = n
        if (occ%has('NUME_INIT')) then
            call occ%get_int('NUME_INIT', first, st)
            if (st%failed()) return
        end if
        if (occ%has('NUME_FIN')) then
            call occ%get_int('NUME_FIN', last, st)
            if (st%failed()) return
        end if
        if (first > n) then
            call occ%error_at('NUME_INIT', 'NUME_INIT = ' // to_text(first) // ' is beyond ' // &
                'the ' // to_text(n) // ' members of the group', st)
            return
        end if
        if (last < first) then
            call occ%error_at('NUME_FIN', 'NUME_FIN = ' // to_text(last) // ' is below ' // &
                'NUME_INIT = ' // to_text(first), st)
            return
        end if
        if (last > n) then
            call occ%error_at('NUME_FIN', 'NUME_FIN = ' // to_text(last) // ' is beyond the ' &
                // to_text(n) // ' members of the group', st)
            return
        end if
        part = members(first:last)
    end subroutine group_slice


    !> One .mess line for a group made ("GROUP_MA TOUT: 40 cells"); with INFO=2 its members'
    !> names too, eight to a line (Code_Aster prints them so at INFO=2).
    subroutine report_group(ctx, mesh, word, name, members, info)
        type(run_context_t), intent(inout) :: ctx
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: word, name
        integer(i4), intent(in) :: members(:), info
        character(len=:), allocatable :: line
        integer(i4) :: i
        call ctx%write_mess('    ' // word // ' ' // name // ' created: ' // &
            to_text(size(members, kind=i4)) // trim(merge(' cells', ' nodes', &
            word == 'GROUP_MA')))
        if (info < 2) return
        line = '     '
        do i = 1, size(members, kind=i4)
            if (word == 'GROUP_MA') then
                line = line // ' ' // cell_name(mesh, members(i))
            else
                line = line // ' ' // node_name(mesh, members(i))
            end if
            if (mod(i, 8) == 0 .or. i == size(members)) then
                call ctx%write_mess(line)
                line = '     '
            end if
        end do
    end subroutine report_group

end module mesh_group_keywords
