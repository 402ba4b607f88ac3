!> A mesh in Code_Aster's ASTER text format (IMPR_RESU FORMAT='RESULTAT' with MAILLAGE
!> alone; the format LIRE_MAILLAGE(FORMAT='ASTER') reads, mesh_aster_reader): TITRE, the
!> nodes (COOR_2D or COOR_3D, E format with 13 digits), the cells by runs of one type in
!> their order, the node groups and the cell groups, FIN.
module mesh_listing
    use kinds, only: i4
    use strings, only: string_t, real_e13
    use mesh_types, only: mesh_t, node_name, cell_name, n_node_groups, n_cell_groups, &
        node_group_name, cell_group_name, nodes_of_group, cells_of_group, CELL_TYPE_NAMES
    implicit none
    private

    public :: aster_mesh_lines

contains

    !> The lines of `mesh` in ASTER format (module header).
    subroutine aster_mesh_lines(mesh, lines)
        type(mesh_t), intent(in) :: mesh
        type(string_t), allocatable, intent(out) :: lines(:)
        integer(i4), allocatable :: members(:)
        character(len=:), allocatable :: row
        integer(i4) :: k, c, p, g, dims
        integer :: n
        allocate (lines(64))
        n = 0
        call add('TITRE')
        if (allocated(mesh%title)) then
            if (len(mesh%title) > 0) call add(' ' // mesh%title)
        end if
        call add('FINSF')
        dims = merge(3_i4, 2_i4, mesh%dim == 3)
        call add(trim(merge('COOR_3D', 'COOR_2D', dims == 3)))
        do k = 1, mesh%n_nodes
            row = node_name(mesh, k)
            do p = 1, dims
                row = row // ' ' // real_e13(mesh%coords(p, k))
            end do
            call add(row)
        end do
        call add('FINSF')
        c = 1
        do while (c <= mesh%n_cells)
            call add(trim(CELL_TYPE_NAMES(mesh%cell_type(c))))
            k = c
            do while (k <= mesh%n_cells)
                if (mesh%cell_type(k) /= mesh%cell_type(c)) exit
                row = cell_name(mesh, k)
                do p = mesh%cell_ptr(k), mesh%cell_ptr(k + 1) - 1
                    row = row // ' ' // node_name(mesh, mesh%cell_nodes(p))
                end do
                call add(row)
                k = k + 1
            end do
            call add('FINSF')
            c = k
        end do
        do g = 1, n_node_groups(mesh)
            call add('GROUP_NO NOM=' // node_group_name(mesh, g))
            members = nodes_of_group(mesh, g)
            do k = 1, size(members, kind=i4)
                call add(node_name(mesh, members(k)))
            end do
            call add('FINSF')
        end do
        do g = 1, n_cell_groups(mesh)
            call add('GROUP_MA NOM=' // cell_group_name(mesh, g))
            members = cells_of_group(mesh, g)
            do k = 1, size(members, kind=i4)
                call add(cell_name(mesh, members(k)))
            end do
            call add('FINSF')
        end do
        call add('FIN')
        lines = lines(1:n)
    contains
        subroutine add(text)
            character(len=*), intent(in) :: text
            type(string_t), allocatable :: bigger(:)
            integer :: m
            if (n == size(lines)) then
                allocate (bigger(2 * size(lines)))
                do m = 1, n
                    call move_alloc(lines(m)%s, bigger(m)%s)
                end do
                call move_alloc(bigger, lines)
            end if
            n = n + 1
            lines(n)%s = text
        end subroutine add
    end subroutine aster_mesh_lines

end module mesh_listing
