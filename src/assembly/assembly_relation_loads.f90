!> The linear relations of the loads of an analysis (model_loads RELATION items: LIAISON_*,
!> FACE_IMPO DNOR ...) as rows on the original equations, their right-hand sides at an
!> instant, and the cells inside a rigid body (LIAISON_SOLIDE) (doc/analysis.md, "Linear
!> relations"). The rows are eliminated by assembly_relations.
module assembly_relation_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, add_context, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use mesh_types, only: node_name
    use model_dof_numbering, only: COMPONENT_NAMES
    use model_types, only: ELEM_NONE
    use model_loads, only: load_set_t, load_item_t, load_value_at, LOAD_RELATION, &
        load_locate, item_slot_name
    use number_limits, only: product_fits
    use assembly_system, only: structure_t
    use assembly_relations, only: relation_rows_t, rows_append
    implicit none
    private

    public :: append_relation_rows, relation_rhs, mark_rigid_cells, describe_row, &
        locate_row

contains

    !> Appends the relations of a load set to rows, on the original equations.
    !>  load_number : in, the EXCIT occurrence (rows remember it for their right-hand side)
    !>  st          : out, a relation on a component no element of the model carries,
    !>                located at its occurrence
    subroutine append_relation_rows(s, load, load_number, rows, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        integer(i4), intent(in) :: load_number
        type(relation_rows_t), intent(inout) :: rows
        type(status_t), intent(out) :: st
        integer(i4) :: k, r, j, n
        integer(i4), allocatable :: eqs(:)
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_RELATION) cycle
            associate (item => load%items(k))
                do r = 1, item%n_rel
                    n = item%rel_ptr(r + 1) - item%rel_ptr(r)
                    if (allocated(eqs)) deallocate (eqs)
                    allocate (eqs(n))
                    do j = 1, n
                        associate (node => item%rel_node(item%rel_ptr(r) + j - 1), &
                                   comp => item%rel_comp(item%rel_ptr(r) + j - 1))
                            eqs(j) = s%dofs%equation(comp, node)
                            if (eqs(j) <= 0) then
                                call set_error(st, STATUS_MODEL_ERROR, 'node ' // &
                                    node_name(s%mesh, node) // ' has no component ' // &
                                    trim(COMPONENT_NAMES(comp)) // ' in the model: no ' // &
                                    'element carries it, a relation cannot hold it')
                                call locate_item(item, st)
                                return
                            end if
                        end associate
                    end do
                    call rows_append(rows, eqs, item%rel_coef(item%rel_ptr(r): &
                        item%rel_ptr(r + 1) - 1), load_number, k, r)
                end do
            end associate
        end do
    end subroutine append_relation_rows

    !> The right-hand sides of the rows of load `load_number` at time t, times factor (its
    !> FONC_MULT), into beta.
    !>  beta : inout, (rows%n)
    !>  st   : out, function errors and values out of range, located at the occurrence
    subroutine relation_rhs(s, load, load_number, rows, t, factor, beta, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        integer(i4), intent(in) :: load_number
        type(relation_rows_t), intent(in) :: rows
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: beta(:)
        type(status_t), intent(out) :: st
        integer(i4) :: r, slot
        real(dp) :: v
        do r = 1, rows%n
            if (rows%load(r) /= load_number) cycle
            associate (item => load%items(rows%item(r)))
                slot = item%rel_slot(rows%rel(r))
                beta(r) = 0.0_dp
                if (slot == 0) cycle
                call load_value_at(item%values(slot), item%kind, slot, t, &
                    s%mesh%coords(:, item%rel_at(rows%rel(r))), v, st, &
                    slot_name=item_slot_name(item, slot))
                if (st%ok() .and. .not. product_fits(factor, v)) call set_error(st, &
                    STATUS_MODEL_ERROR, item_slot_name(item, slot) // ' = ' // real_e13(v) &
                    // ' times FONC_MULT ' // real_e13(factor) // ' overflows')
                call load_locate(item, slot, st)
                if (st%failed()) return
                beta(r) = factor * v
            end associate
        end do
    end subroutine relation_rhs

    !> Marks the cells inside a rigid body of the load (LIAISON_SOLIDE): every node of the
    !> cell in the body. Under the body's relations such a cell only moves rigidly and stores
    !> no energy, so the analysis leaves it out (its forces are exactly 0; computed, they
    !> would be the round-off of a stiff cell's K times a rigid motion).
    !>  rigid : inout, (n_cells)
    subroutine mark_rigid_cells(s, load, rigid)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        logical, intent(inout) :: rigid(:)
        logical, allocatable :: in_body(:)
        integer(i4) :: k, c
        allocate (in_body(s%mesh%n_nodes))
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_RELATION) cycle
            if (.not. allocated(load%items(k)%solid_nodes)) cycle
            in_body = .false.
            in_body(load%items(k)%solid_nodes) = .true.
            do c = 1, s%mesh%n_cells
                if (s%model%element(c) == ELEM_NONE) cycle
                if (all(in_body(s%mesh%cell_nodes(s%mesh%cell_ptr(c): &
                    s%mesh%cell_ptr(c + 1) - 1)))) rigid(c) = .true.
            end do
        end do
    end subroutine mark_rigid_cells

    !> "N3 DX - 2 N4 DY = beta"-like text of row r (its first terms), for messages.
    function describe_row(s, rows, r) result(text)
        type(structure_t), intent(in) :: s
        type(relation_rows_t), intent(in) :: rows
        integer(i4), intent(in) :: r
        character(len=:), allocatable :: text
        integer(i4) :: k, eq, shown
        real(dp) :: c
        text = ''
        shown = 0
        do k = rows%ptr(r), rows%ptr(r + 1) - 1
            shown = shown + 1
            if (shown > 6) then
                text = text // ' ...'
                exit
            end if
            eq = rows%eq(k)
            c = rows%coef(k)
            if (shown > 1) text = text // merge(' - ', ' + ', c < 0.0_dp)
            if (shown == 1 .and. c < 0.0_dp) text = text // '-'
            if (abs(abs(c) - 1.0_dp) > 0.0_dp) text = text // trim(real_e13(abs(c))) // ' '
            text = text // node_name(s%mesh, s%dofs%equation_node(eq)) // ' ' // &
                trim(COMPONENT_NAMES(s%dofs%equation_component(eq)))
        end do
    end function describe_row

    !> Locates st at the occurrence of row r (its load's item).
    subroutine locate_row(loads_item, st)
        type(load_item_t), intent(in) :: loads_item
        type(status_t), intent(inout) :: st
        call locate_item(loads_item, st)
    end subroutine locate_row

    ! Locates st at an item's occurrence (keyword only, no slot).
    subroutine locate_item(item, st)
        type(load_item_t), intent(in) :: item
        type(status_t), intent(inout) :: st
        if (st%ok() .or. .not. allocated(item%file)) return
        if (allocated(st%file)) return
        call add_context(st, file=item%file, line=item%line, column=item%col, &
                         command=item%command, keyword=item%keyword)
    end subroutine locate_item

end module assembly_relation_loads
