!> Helpers shared by the command handlers of the mesh and model layers: locating an error
!> found by a lower layer at the deck keyword it concerns, and turning GROUP_MA / TOUT
!> keywords into cell lists with errors located at the keyword.
module mesh_command_support
    use kinds, only: i4
    use status, only: status_t
    use strings, only: string_t, starts_with
    use deck_command, only: keyword_set_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group
    implicit none
    private

    public :: relocate_error, read_groups, group_cells, all_cells

contains

    !> Re-reports a failed status at keyword `key` of `kws` (deck file, line, column,
    !> COMMAND/FACTOR/KEY), keeping its category and message. A lower layer that named a
    !> more precise keyword of the same factor (st%keyword = 'FACTOR/KEY') wins over `key`.
    !> Does nothing when st is ok.
    !>  kws : in, the command or factor occurrence;  key : in, default keyword
    !>  st  : inout, the status to relocate
    subroutine relocate_error(kws, key, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message, where
        integer :: code
        if (st%ok()) return
        code = st%code
        message = 'unspecified failure'
        if (allocated(st%message)) message = st%message
        where = key
        if (allocated(st%keyword) .and. allocated(kws%scope)) then
            if (len(kws%scope) > 0 .and. starts_with(st%keyword, kws%scope // '/')) then
                where = st%keyword(len(kws%scope) + 2:)
                if (.not. kws%has(where)) where = key
            end if
        end if
        call kws%error_at(where, message, st, code=code)
    end subroutine relocate_error

    !> The group names of keyword `key` (e.g. GROUP_MA), each checked against the cell
    !> groups of `mesh`.
    !>  names : out, the names as written;  groups : out, their group numbers
    !>  st    : out, error located at `key`: no such group (with a did-you-mean)
    subroutine read_groups(kws, key, mesh, names, groups, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: groups(:)
        type(status_t), intent(out) :: st
        integer(i4) :: g
        call kws%get_texts(key, names, st)
        if (st%failed()) return
        allocate (groups(size(names)))
        do g = 1, size(names)
            groups(g) = find_cell_group(mesh, names(g)%s, st)
            if (st%failed()) then
                call relocate_error(kws, key, st)
                return
            end if
        end do
    end subroutine read_groups

    !> All cells of the groups of keyword `key`, concatenated in the order given.
    !>  st : out, error located at `key` for a group missing in the mesh
    subroutine group_cells(kws, key, mesh, cells, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), members(:)
        integer(i4) :: g, n
        call read_groups(kws, key, mesh, names, groups, st)
        if (st%failed()) return
        n = 0
        do g = 1, size(groups)
            n = n + size(cells_of_group(mesh, groups(g)), kind=i4)
        end do
        allocate (cells(n))
        n = 0
        do g = 1, size(groups)
            members = cells_of_group(mesh, groups(g))
            cells(n + 1:n + size(members)) = members
            n = n + size(members, kind=i4)
        end do
    end subroutine group_cells

    !> 1, 2, ..., n_cells (TOUT='OUI').
    function all_cells(mesh) result(cells)
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable :: cells(:)
        integer(i4) :: c
        allocate (cells(mesh%n_cells))
        do c = 1, mesh%n_cells
            cells(c) = c
        end do
    end function all_cells

end module mesh_command_support
