!> Loads of a static analysis on the original equations: which equations DDL_IMPO imposes,
!> their values at an instant, and the external force vector at an instant (FORCE_NODALE
!> at nodes; FORCE_COQUE / PRES_REP / FORCE_CONTOUR integrated at the element's load points
!> with the functions evaluated there, design.md "Loads"). Every value is multiplied by the
!> FONC_MULT factor of its EXCIT occurrence (evaluated by the caller at the instant).
module assembly_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use mesh_types, only: cell_label, node_name
    use model_types, only: is_plate, is_plane_edge
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS
    use model_loads, only: load_set_t, load_item_t, load_value_at, LOAD_DDL_IMPO, &
        LOAD_FORCE_NODALE, LOAD_FORCE_COQUE, LOAD_PRES_REP, LOAD_FORCE_CONTOUR, SLOT_PRES, &
        LOAD_KIND_NAMES, load_locate, load_slot_name
    use number_limits, only: product_fits
    use strings, only: to_text
    use element_loads, only: plate_load_points, plate_pressure_forces, plate_surface_forces, &
        edge_load_points, edge_line_forces, PLATE_LOAD_MAX_POINTS, EDGE_POINT_COUNT, &
        plate_load_point_count
    use assembly_system, only: structure_t
    implicit none
    private

    public :: mark_imposed, impose_values, add_external_forces, record_imposed

    !> Relative difference under which two values imposed on one component are the same.
    real(dp), parameter :: SAME_IMPOSED_VALUE = 1.0e-12_dp

contains

    !> Marks the equations a load set imposes (DDL_IMPO).
    !>  imposed : inout, (n_equations)
    !>  st      : out, STATUS_MODEL_ERROR when a node has no such component in the model
    subroutine mark_imposed(s, load, imposed, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        logical, intent(inout) :: imposed(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i, comp, eq
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_DDL_IMPO) cycle
            associate (item => load%items(k))
                do i = 1, size(item%nodes)
                    do comp = 1, N_COMPONENTS
                        if (.not. item%values(comp)%given) cycle
                        eq = s%dofs%equation(comp, item%nodes(i))
                        if (eq <= 0) then
                            call set_error(st, STATUS_MODEL_ERROR, 'DDL_IMPO: node ' // &
                                node_name(s%mesh, item%nodes(i)) // ' has no component ' // &
                                trim(COMPONENT_NAMES(comp)) // ' in the model')
                            return
                        end if
                        imposed(eq) = .true.
                    end do
                end do
            end associate
        end do
    end subroutine mark_imposed

    !> Writes the DDL_IMPO values at time t (times factor) into u.
    subroutine impose_values(s, load, t, factor, u, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: u(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i, comp, eq, node
        real(dp) :: v
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_DDL_IMPO) cycle
            associate (item => load%items(k))
                do i = 1, size(item%nodes)
                    node = item%nodes(i)
                    do comp = 1, N_COMPONENTS
                        if (.not. item%values(comp)%given) cycle
                        eq = s%dofs%equation(comp, node)
                        if (eq <= 0) cycle
                        call load_value_at(item%values(comp), item%kind, comp, t, &
                            s%mesh%coords(:, node), v, st)
                        if (st%ok()) call check_factor(factor, v, item%kind, comp, st)
                        call load_locate(item, comp, st)
                        if (st%failed()) return
                        u(eq) = factor * v
                    end do
                end do
            end associate
        end do
    end subroutine impose_values

    !> Records the DDL_IMPO values of load set number `load_number` at time t (times
    !> factor) and finds a component imposed twice with different values: Code_Aster refuses
    !> conflicting imposed values, and applying them in turn would silently keep the last.
    !>  value, owner : inout, (n_equations) and (2, n_equations): the value imposed so far
    !>                 and (load number, item) that imposed it, owner(1, eq) = 0 for none
    !>  first : out, on a conflict the owner of the other value (load number, item)
    !>  st : out, the conflict, located at the occurrence found second (the caller names the
    !>       first one); function errors and values out of range, located
    subroutine record_imposed(s, load, load_number, t, factor, value, owner, first, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        integer(i4), intent(in) :: load_number
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: value(:)
        integer(i4), intent(inout) :: owner(:, :)
        integer(i4), intent(out) :: first(2)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i, comp, eq, node
        real(dp) :: v
        first = 0
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_DDL_IMPO) cycle
            associate (item => load%items(k))
                do i = 1, size(item%nodes)
                    node = item%nodes(i)
                    do comp = 1, N_COMPONENTS
                        if (.not. item%values(comp)%given) cycle
                        eq = s%dofs%equation(comp, node)
                        if (eq <= 0) cycle
                        call load_value_at(item%values(comp), item%kind, comp, t, &
                            s%mesh%coords(:, node), v, st)
                        if (st%ok()) call check_factor(factor, v, item%kind, comp, st)
                        call load_locate(item, comp, st)
                        if (st%failed()) return
                        v = factor * v
                        if (owner(1, eq) == 0) then
                            owner(:, eq) = [load_number, k]
                            value(eq) = v
                        else if (abs(v - value(eq)) > SAME_IMPOSED_VALUE * &
                                 max(abs(v), abs(value(eq)))) then
                            first = owner(:, eq)
                            call set_error(st, STATUS_MODEL_ERROR, 'node ' // &
                                node_name(s%mesh, node) // ' ' // trim(COMPONENT_NAMES(comp)) &
                                // ' is imposed twice with different values at INST ' // &
                                to_text(t) // ': ' // to_text(v) // ' here, ' // &
                                to_text(value(eq)) // ' by the DDL_IMPO')
                            call load_locate(item, comp, st)
                            return
                        end if
                    end do
                end do
            end associate
        end do
    end subroutine record_imposed

    !> Adds the external forces of a load set at time t (times factor) to fext.
    !>  st : out, function evaluation errors; a load on a cell of the wrong kind; a nodal
    !>       force on a component the node does not have
    subroutine add_external_forces(s, load, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i
        do k = 1, load%n_items
            associate (item => load%items(k))
                select case (item%kind)
                case (LOAD_FORCE_NODALE)
                    call nodal_forces(s, item, t, factor, fext, st)
                case (LOAD_FORCE_COQUE, LOAD_PRES_REP)
                    do i = 1, size(item%cells)
                        call plate_cell_forces(s, item, item%cells(i), t, factor, fext, st)
                        if (st%failed()) exit
                    end do
                case (LOAD_FORCE_CONTOUR)
                    do i = 1, size(item%cells)
                        call edge_cell_forces(s, item, item%cells(i), t, factor, fext, st)
                        if (st%failed()) exit
                    end do
                end select
            end associate
            if (st%failed()) return
        end do
    end subroutine add_external_forces

    subroutine nodal_forces(s, item, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        integer(i4) :: i, comp, eq
        real(dp) :: v
        do i = 1, size(item%nodes)
            do comp = 1, N_COMPONENTS
                if (.not. item%values(comp)%given) cycle
                eq = s%dofs%equation(comp, item%nodes(i))
                if (eq <= 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'FORCE_NODALE: node ' // &
                        node_name(s%mesh, item%nodes(i)) // ' has no component ' // &
                        trim(COMPONENT_NAMES(comp)) // ' in the model')
                    return
                end if
                call load_value_at(item%values(comp), item%kind, comp, t, &
                    s%mesh%coords(:, item%nodes(i)), v, st)
                if (st%ok()) call check_factor(factor, v, item%kind, comp, st)
                call load_locate(item, comp, st)
                if (st%failed()) return
                fext(eq) = fext(eq) + factor * v
            end do
        end do
    end subroutine nodal_forces

    !> FORCE_COQUE / PRES_REP on one plate cell: PRES (force = -PRES n) or FX/FY/FZ.
    subroutine plate_cell_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(3, 4), xg(3, PLATE_LOAD_MAX_POINTS), wg(PLATE_LOAD_MAX_POINTS)
        real(dp) :: q(3, PLATE_LOAD_MAX_POINTS), fe(12)
        integer(i4) :: nn, np, g, a, comp, p0, eq
        logical :: pressure
        if (.not. is_plate(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(item%kind)) // &
                ' applies to plate (DKT) cells, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        np = plate_load_point_count(nn)
        call plate_load_points(x(:, 1:nn), nn, xg, wg, st)
        if (st%failed()) return
        pressure = item%values(SLOT_PRES)%given
        q = 0.0_dp
        do g = 1, np
            do comp = 1, 3
                if (pressure .and. comp > 1) exit
                if (pressure) then
                    call load_value_at(item%values(SLOT_PRES), item%kind, SLOT_PRES, t, &
                        xg(:, g), q(1, g), st)
                    if (st%ok()) call check_factor(wg(g), q(1, g), item%kind, SLOT_PRES, st)
                    if (st%ok()) call check_factor(factor, q(1, g) * wg(g), item%kind, &
                                                   SLOT_PRES, st)
                    call load_locate(item, SLOT_PRES, st)
                else if (item%values(comp)%given) then
                    call load_value_at(item%values(comp), item%kind, comp, t, xg(:, g), &
                        q(comp, g), st)
                    if (st%ok()) call check_factor(wg(g), q(comp, g), item%kind, comp, st)
                    if (st%ok()) call check_factor(factor, q(comp, g) * wg(g), item%kind, &
                                                   comp, st)
                    call load_locate(item, comp, st)
                end if
                if (st%failed()) return
            end do
        end do
        if (pressure) then
            call plate_pressure_forces(x(:, 1:nn), nn, q(1, 1:np), fe(1:3 * nn), st)
        else
            call plate_surface_forces(x(:, 1:nn), nn, q(:, 1:np), fe(1:3 * nn), st)
        end if
        if (st%failed()) return
        do a = 1, nn
            do comp = 1, 3
                eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                if (eq > 0) fext(eq) = fext(eq) + factor * fe(3 * (a - 1) + comp)
            end do
        end do
    end subroutine plate_cell_forces

    !> FORCE_CONTOUR FX, FY on one SEG2 edge of a plane model (per unit length, unit depth).
    subroutine edge_cell_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(2, 2), xg(2, EDGE_POINT_COUNT), wg(EDGE_POINT_COUNT)
        real(dp) :: q(2, EDGE_POINT_COUNT), fe(4)
        integer(i4) :: g, a, comp, p0, eq
        if (.not. is_plane_edge(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, 'FORCE_CONTOUR applies to SEG2 edges ' // &
                'of a D_PLAN/C_PLAN model, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        x = s%mesh%coords(1:2, s%mesh%cell_nodes(p0:p0 + 1))
        call edge_load_points(x, xg, wg, st)
        if (st%failed()) return
        q = 0.0_dp
        do g = 1, EDGE_POINT_COUNT
            do comp = 1, 2
                if (.not. item%values(comp)%given) cycle
                call load_value_at(item%values(comp), item%kind, comp, t, &
                    [xg(1, g), xg(2, g), 0.0_dp], q(comp, g), st)
                if (st%ok()) call check_factor(wg(g), q(comp, g), item%kind, comp, st)
                if (st%ok()) call check_factor(factor, q(comp, g) * wg(g), item%kind, comp, &
                                               st)
                call load_locate(item, comp, st)
                if (st%failed()) return
            end do
        end do
        call edge_line_forces(x, q, fe, st)
        if (st%failed()) return
        do a = 1, 2
            do comp = 1, 2
                eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                if (eq > 0) fext(eq) = fext(eq) + factor * fe(2 * (a - 1) + comp)
            end do
        end do
    end subroutine edge_cell_forces

    ! A load value times a factor (the FONC_MULT of its EXCIT, an integration weight) must
    ! stay inside the magnitudes products may be formed from (number_limits): decided
    ! before multiplying, so the check cannot overflow.
    subroutine check_factor(factor, value, kind, slot, st)
        real(dp), intent(in) :: factor, value
        integer(i4), intent(in) :: kind, slot
        type(status_t), intent(inout) :: st
        if (product_fits(factor, value)) return
        call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(kind)) // ' ' // &
            load_slot_name(kind, slot) // ' = ' // to_text(value) // ' times ' // &
            to_text(factor) // ' (FONC_MULT, or the area or length it acts on) overflows')
    end subroutine check_factor

end module assembly_loads
