!> Command handler of the model layer: AFFE_MODELE (doc/deck-language.md).
module model_commands
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cell_label, CELL_TYPE_NAMES
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error, read_groups, all_cells
    use mesh_types, only: cells_of_group
    use model_types, only: model_t, model_init, assign_modelisation, element_for, &
        ELEM_NONE, ELEMENT_NAMES, N_ELEMENT_KINDS
    use model_dof_numbering, only: number_dofs
    use model_concept, only: model_concept_t
    implicit none
    private

    public :: run_affe_modele

contains

    !> AFFE_MODELE(MAILLAGE, AFFE=_F(TOUT='OUI' | GROUP_MA, MODELISATION)): the element of
    !> every cell (later occurrences override earlier ones), then the DOF numbering. The
    !> .mess gets the cells per element kind and the number of equations.
    !>  result : out, a model_concept_t (with its own copy of the mesh)
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
            mc%mesh = p%mesh
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
        call number_dofs(mc%model, mc%mesh, mc%dofs)
        do k = 1, N_ELEMENT_KINDS
            i = count(mc%model%element == k, kind=i4)
            if (i > 0) call ctx%write_mess('    ' // ELEMENT_NAMES(k) // ' ' // to_text(i) // &
                                           ' cells')
        end do
        call ctx%write_mess('    equations ' // to_text(mc%dofs%n_equations))
        call move_alloc(mc, result)
    end subroutine run_affe_modele

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
