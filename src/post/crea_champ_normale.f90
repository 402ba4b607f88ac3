!> CREA_CHAMP OPERATION='NORMALE' (Code_Aster U4.72.04, crea_champ.py block b_norm: MODELE
!> and GROUP_MA required): the unit normal at the nodes of the boundary cells of GROUP_MA
!> (edges of a 2D mesh, faces of a 3D one), as a NOEU_GEOM_R field, X Y in 2D and X Y Z in
!> 3D, on those nodes only. At a node shared by several cells the normal is the mean of
!> the cells' unit normals there, normalised: the same normal FACE_IMPO DNOR imposes
!> (model_relations node_directions, after Code_Aster's canort; an edge's normal is
!> (t_y, -t_x) of its tangent from its first node to its second).
!> Errors (located at GROUP_MA): an unknown group, a cell that is not an edge (2D) or a face
!> (3D), a degenerate cell, normals that cancel at a node; at TYPE_CHAM: another type than
!> NOEU_GEOM_R.
module crea_champ_normale
    use kinds, only: dp, i4
    use status, only: status_t, clear_status, STATUS_MODEL_ERROR
    use strings, only: string_t
    use deck_command, only: command_t, keyword_set_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group
    use model_types, only: model_t
    use model_relations, only: node_directions
    use field_types, only: field_init_nodes
    use field_concept, only: field_concept_t
    use crea_champ_combine, only: read_support
    implicit none
    private

    public :: crea_normale

contains

    !> OPERATION='NORMALE' (module header) into `out`.
    subroutine crea_normale(cmd, type_cham, out, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: type_cham
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(string_t), allocatable :: names(:), cmps(:)
        logical, allocatable :: in_group(:), on_node(:)
        integer(i4), allocatable :: cells(:), nodes(:)
        real(dp), allocatable :: normals(:, :)
        integer(i4) :: k, g, c, p, dim
        if (type_cham /= 'NOEU_GEOM_R') then
            call cmd%error_at('TYPE_CHAM', 'OPERATION=''NORMALE'' makes a NOEU_GEOM_R ' // &
                'field, not ' // type_cham, st, STATUS_MODEL_ERROR)
            return
        end if
        if (.not. cmd%has('MODELE') .or. .not. cmd%has('GROUP_MA')) then
            call cmd%error_at('OPERATION', 'OPERATION=''NORMALE'' needs MODELE and ' // &
                'GROUP_MA (the boundary cells whose normal is taken)', st, STATUS_MODEL_ERROR)
            return
        end if
        call read_support(cmd, out, mesh, model, st)
        if (st%ok()) call cmd%get_texts('GROUP_MA', names, st)
        if (st%failed()) return
        allocate (in_group(mesh%n_cells), source=.false.)
        do k = 1, size(names)
            g = find_cell_group(mesh, names(k)%s, st)
            if (st%failed()) then
                call relocate(cmd, 'GROUP_MA', st)
                return
            end if
            in_group(cells_of_group(mesh, g)) = .true.
        end do
        cells = pack([(c, c = 1, mesh%n_cells)], in_group)
        allocate (on_node(mesh%n_nodes), source=.false.)
        do k = 1, size(cells)
            c = cells(k)
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                on_node(mesh%cell_nodes(p)) = .true.
            end do
        end do
        nodes = pack([(p, p = 1, mesh%n_nodes)], on_node)
        allocate (normals(3, size(nodes)))
        call node_directions(mesh, cells, nodes, .false., normals, st)
        if (st%failed()) then
            call relocate(cmd, 'GROUP_MA', st)
            return
        end if
        dim = merge(2_i4, 3_i4, mesh%dim == 2)
        allocate (cmps(dim))
        cmps(1)%s = 'X'
        cmps(2)%s = 'Y'
        if (dim == 3) cmps(3)%s = 'Z'
        call field_init_nodes(out%field, 'GEOM_R', cmps, mesh%n_nodes, st)
        if (st%failed()) return
        out%field%node_values = 0.0_dp
        out%field%node_has = .false.
        do k = 1, size(nodes)
            out%field%node_values(1:dim, nodes(k)) = normals(1:dim, k)
            out%field%node_has(1:dim, nodes(k)) = .true.
        end do
    end subroutine crea_normale

    ! Locates a failed status at `key`, keeping its message.
    subroutine relocate(kws, key, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message
        message = st%message
        call clear_status(st)
        call kws%error_at(key, message, st, STATUS_MODEL_ERROR)
    end subroutine relocate

end module crea_champ_normale
