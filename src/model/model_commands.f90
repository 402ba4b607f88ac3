!> Command handler of the model layer: AFFE_MODELE (doc/deck-language.md).
module model_commands
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper, real_short
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cell_label, CELL_TYPE_NAMES, cell_node_list
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error, read_groups, all_cells
    use mesh_types, only: cells_of_group
    use model_types, only: model_t, model_init, assign_modelisation, element_for, &
        ELEM_NONE, ELEM_DKQ, ELEMENT_NAMES, N_ELEMENT_KINDS
    use model_dof_numbering, only: number_dofs
    use model_concept, only: model_concept_t
    implicit none
    private

    public :: run_affe_modele, quad_warp

    !> Warp of a DKQ above which the model check warns: the distance of corner 4 from the
    !> plane of corners 1, 2, 3 relative to side 1-4, Code_Aster's measure and threshold
    !> (dxqpgl, alarm ELEMENTS4_80: "1D-4 en dur"). A DKQ is a flat element: on a warped
    !> quadrangle its membrane and bending are computed in a mean plane the corners are not
    !> in, and its results (and the convergence of a contact analysis) degrade with the warp.
    real(dp), parameter :: DKQ_WARP_TOLERANCE = 1.0e-4_dp

contains

    !> AFFE_MODELE(MAILLAGE, AFFE=_F(TOUT='OUI' | GROUP_MA, MODELISATION)): the element of
    !> every cell (later occurrences override earlier ones), then the DOF numbering. The
    !> .mess gets the cells per element kind and the number of equations.
    !>  result : out, a model_concept_t (referring to the mesh)
    !>  st     : out, located at the keyword: a GROUP_MA missing in the mesh (did-you-mean),
    !>           a MODELISATION with no element on a cell of the group, a model with no
    !>           element at all (at AFFE)
    subroutine run_affe_modele(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(model_concept_t), allocatable :: mc
        class(concept_t), pointer :: p
        integer(i4) :: i, k
        call cmd%get_concept('MAILLAGE', p, st)
        if (st%failed()) return
        allocate (mc)
        select type (p)
        type is (mesh_concept_t)
            mc%mesh => p%mesh       ! referred to: later in-place edits are seen (model_concept)
        class default
            call cmd%error_at('MAILLAGE', 'expected a mesh (maillage), got ' // &
                              p%type_name(), st)
            return
        end select
        call model_init(mc%model, mc%mesh)
        do i = 1, cmd%count('AFFE')
            call affect_occurrence(cmd%occurrence('AFFE', i), mc%mesh, mc%model, st)
            if (st%failed()) return
        end do
        if (all(mc%model%element == ELEM_NONE)) then
            call cmd%error_at('AFFE', 'no cell of the mesh carries an element', st, &
                              code=STATUS_MODEL_ERROR)
            return
        end if
        call warn_warped_plates(ctx, mc%mesh, mc%model)
        call number_dofs(mc%model, mc%mesh, mc%dofs)
        do k = 1, N_ELEMENT_KINDS
            i = count(mc%model%element == k, kind=i4)
            if (i > 0) call ctx%write_mess('    ' // ELEMENT_NAMES(k) // ' ' // to_text(i) // &
                                           ' cells')
        end do
        call ctx%write_mess('    equations ' // to_text(mc%dofs%n_equations))
        call move_alloc(mc, result)
    end subroutine run_affe_modele

    !> Warp of a quadrangle as Code_Aster measures it (dxqpgl): the distance of corner 4 from
    !> the plane of corners 1, 2, 3 divided by |x4 - x1|; 0 for corners 1, 2, 3 aligned
    !> (mesh_finish refuses such a cell) or a zero side 1-4.
    !>  x : in, x(3, 4) the corners;  warp : out;  distance : out, the distance itself
    pure subroutine quad_warp(x, warp, distance)
        real(dp), intent(in) :: x(3, 4)
        real(dp), intent(out) :: warp, distance
        real(dp) :: u(3), t12(3), t13(3), t14(3), normu, norm4
        t12 = x(:, 2) - x(:, 1)
        t13 = x(:, 3) - x(:, 1)
        t14 = x(:, 4) - x(:, 1)
        u = [t12(2) * t13(3) - t13(2) * t12(3), t12(3) * t13(1) - t13(3) * t12(1), &
             t12(1) * t13(2) - t13(1) * t12(2)]
        normu = norm2(u)
        norm4 = norm2(t14)
        warp = 0.0_dp
        distance = 0.0_dp
        if (normu > 0.0_dp .and. norm4 > 0.0_dp) then
            distance = abs(dot_product(u, t14)) / normu
            warp = distance / norm4
        end if
    end subroutine quad_warp

    ! One warning in the .mess, located at the most warped DKQ's line in the mesh file, when
    ! DKQ cells are warped beyond DKQ_WARP_TOLERANCE: how many, and the measured warp.
    subroutine warn_warped_plates(ctx, mesh, model)
        type(run_context_t), intent(inout) :: ctx
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        integer(i4) :: c, worst, n_warped
        real(dp) :: warp, worst_warp, worst_distance, distance
        real(dp) :: x(3, 4)
        n_warped = 0
        worst = 0
        worst_warp = 0.0_dp
        worst_distance = 0.0_dp
        do c = 1, mesh%n_cells
            if (model%element(c) /= ELEM_DKQ) cycle
            x = mesh%coords(:, cell_node_list(mesh, c))
            call quad_warp(x, warp, distance)
            if (.not. warp > DKQ_WARP_TOLERANCE) cycle
            n_warped = n_warped + 1
            if (warp > worst_warp) then
                worst = c
                worst_warp = warp
                worst_distance = distance
            end if
        end do
        if (n_warped == 0) return
        call ctx%write_warning(mesh%file // ':' // to_text(mesh%cell_line(worst)) // &
            ': warning: AFFE_MODELE: ' // to_text(n_warped) // ' DKQ cell(s) warped beyond ' &
            // real_short(DKQ_WARP_TOLERANCE) // ' (Code_Aster''s alarm ELEMENTS4_80); the ' // &
            'most warped, ' // cell_label(mesh, worst) // ', has corner 4 at ' // &
            real_short(worst_distance) // ' from the plane of corners 1-3, a warp of ' // &
            real_short(worst_warp) // ' of its side 1-4: a flat DKQ on it is inaccurate ' // &
            '(split it into DKT triangles or flatten it)')
    end subroutine warn_warped_plates

    ! One AFFE occurrence: TOUT='OUI' (cells of other types are skipped) or each GROUP_MA.
    subroutine affect_occurrence(occ, mesh, model, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(inout) :: model
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:), mods(:)
        integer(i4), allocatable :: groups(:)
        integer(i4) :: g
        call occ%get_texts('MODELISATION', mods, st)
        if (st%failed()) return
        if (occ%has('TOUT')) then
            call assign_cells(occ, mesh, model, all_cells(mesh), mods, '', .true., st)
            return
        end if
        call read_groups(occ, 'GROUP_MA', mesh, names, groups, st)
        if (st%failed()) return
        do g = 1, size(groups)
            call assign_cells(occ, mesh, model, cells_of_group(mesh, groups(g)), mods, &
                              names(g)%s, .false., st)
            if (st%failed()) return
        end do
    end subroutine affect_occurrence

    ! One modelisation: assign_modelisation (its messages). Several (MODELISATION=('DKT',
    ! 'DIS_T')): each cell takes the first that has an element on its type; a cell that
    ! none fits is an error unless TOUT (skip).
    subroutine assign_cells(occ, mesh, model, cells, mods, group, skip, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(inout) :: model
        integer(i4), intent(in) :: cells(:)
        type(string_t), intent(in) :: mods(:)
        character(len=*), intent(in) :: group
        logical, intent(in) :: skip
        type(status_t), intent(out) :: st
        integer(i4) :: i, k, kind, n_fit
        if (size(mods) == 1) then
            call assign_modelisation(model, mesh, cells, mods(1)%s, st, group=group, &
                                     skip_incompatible=skip)
            call relocate_error(occ, 'MODELISATION', st)
            return
        end if
        n_fit = 0
        do i = 1, size(cells)
            kind = ELEM_NONE
            do k = 1, size(mods)
                kind = element_for(to_upper(mods(k)%s), mesh%cell_type(cells(i)))
                if (kind > ELEM_NONE) exit
            end do
            if (kind > ELEM_NONE) then
                model%element(cells(i)) = kind
                n_fit = n_fit + 1
            else if (.not. skip) then
                call set_error(st, STATUS_MODEL_ERROR, 'no MODELISATION given has an ' // &
                    'element on ' // cell_label(mesh, cells(i), group) // ' of type ' // &
                    trim(CELL_TYPE_NAMES(mesh%cell_type(cells(i)))))
                call relocate_error(occ, 'MODELISATION', st)
                return
            end if
        end do
        if (n_fit == 0 .and. size(cells) > 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'no MODELISATION given fits a cell')
            call relocate_error(occ, 'MODELISATION', st)
        end if
    end subroutine assign_cells

end module model_commands
