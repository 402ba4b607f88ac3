!> Loads of a static analysis on the original equations: which equations DDL_IMPO imposes,
!> their values at an instant, and the external force vector at an instant (FORCE_NODALE
!> at nodes; FORCE_COQUE / PRES_REP known at the plate's nodes and FORCE_CONTOUR at the
!> edge's Gauss points, as Code_Aster discretises them: element_loads, design.md "Loads";
!> PRE_EPSI's initial strains at the RIGI points: assembly_pre_epsi).
!> Every value is multiplied by the FONC_MULT factor of its EXCIT occurrence (evaluated by
!> the caller at the instant).
module assembly_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: real_e13, to_text
    use mesh_types, only: cell_label, node_name, cell_measure
    use model_types, only: is_plate, is_plane_edge
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS
    use model_loads, only: load_set_t, load_item_t, load_value_at, LOAD_DDL_IMPO, &
        LOAD_FORCE_NODALE, LOAD_FORCE_COQUE, LOAD_PRES_REP, LOAD_FORCE_CONTOUR, SLOT_PRES, &
        LOAD_KIND_NAMES, load_locate, load_slot_name, LOAD_PRE_EPSI, LOAD_PRE_EPSI_PLATE
    use assembly_pre_epsi, only: add_pre_epsi_forces
    use number_limits, only: product_fits
    use element_loads, only: plate_nodal_pressure, plate_nodal_forces, edge_load_points, &
        edge_line_forces, edge_points_t, MAX_EDGE_POINTS, MAX_EDGE_NODES
    use assembly_system, only: structure_t
    implicit none
    private

    public :: mark_imposed, impose_values, add_external_forces, check_imposed_owners, &
        record_imposed

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
                        if (eq <= 0 .and. item%blocage) cycle
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

    !> Records which load imposes each equation and refuses an equation imposed by a
    !> kinematic load (AFFE_CHAR_CINE) and by another load: Code_Aster cannot eliminate an
    !> equation and dualise it too (nor combine two eliminations of it), and the values could
    !> differ. Repeats inside one load are left to that load (the last value wins).
    !>  load  : in, the load set of EXCIT occurrence `which`
    !>  owner : inout, (n_equations) the EXCIT occurrence imposing each equation (0: none);
    !>          negative for a kinematic load
    !>  st    : out, STATUS_MODEL_ERROR naming the node and component
    subroutine check_imposed_owners(s, load, which, owner, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        integer(i4), intent(in) :: which
        integer(i4), intent(inout) :: owner(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i, comp, eq, me
        me = which
        if (load%kinematic) me = -which
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_DDL_IMPO) cycle
            associate (item => load%items(k))
                do i = 1, size(item%nodes)
                    do comp = 1, N_COMPONENTS
                        if (.not. item%values(comp)%given) cycle
                        eq = s%dofs%equation(comp, item%nodes(i))
                        if (eq <= 0) cycle
                        if (owner(eq) /= 0 .and. owner(eq) /= me .and. &
                            (owner(eq) < 0 .or. me < 0)) then
                            call set_error(st, STATUS_MODEL_ERROR, 'node ' // &
                                node_name(s%mesh, item%nodes(i)) // ' component ' // &
                                trim(COMPONENT_NAMES(comp)) // ' is imposed by EXCIT ' // &
                                'occurrences ' // to_text(abs(owner(eq))) // ' and ' // &
                                to_text(which) // ', one of them an AFFE_CHAR_CINE: ' // &
                                'an eliminated value must be imposed once (remove it from ' // &
                                'one load)')
                            return
                        end if
                        owner(eq) = me
                    end do
                end do
            end associate
        end do
    end subroutine check_imposed_owners

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
                        call imposed_at(s, item, node, comp, t, factor, eq, v, st)
                        if (st%failed()) return
                        if (eq <= 0) cycle
                        u(eq) = v
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
                        call imposed_at(s, item, node, comp, t, factor, eq, v, st)
                        if (st%failed()) return
                        if (eq <= 0) cycle
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

    !> The value a DDL_IMPO item imposes on (node, comp) at time t, times factor, and its
    !> equation (eq = 0: the component is not given, or not an unknown of the model).
    !>  st : out, function errors and values out of range, located at the item
    subroutine imposed_at(s, item, node, comp, t, factor, eq, v, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: node, comp
        real(dp), intent(in) :: t, factor
        integer(i4), intent(out) :: eq
        real(dp), intent(out) :: v
        type(status_t), intent(out) :: st
        eq = 0
        v = 0.0_dp
        if (.not. item%values(comp)%given) return
        eq = s%dofs%equation(comp, node)
        if (eq <= 0) return
        call load_value_at(item%values(comp), item%kind, comp, t, s%mesh%coords(:, node), v, st)
        if (st%ok()) call check_factor(factor, v, item%kind, comp, st)
        call load_locate(item, comp, st)
        if (st%ok()) v = factor * v
    end subroutine imposed_at

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
                        if (item%kind == LOAD_PRES_REP .and. &
                            is_plane_edge(s%model%element(item%cells(i)))) then
                            call edge_cell_forces(s, item, item%cells(i), t, factor, fext, st)
                        else
                            call plate_cell_forces(s, item, item%cells(i), t, factor, fext, st)
                        end if
                        if (st%failed()) exit
                    end do
                case (LOAD_FORCE_CONTOUR)
                    do i = 1, size(item%cells)
                        call edge_cell_forces(s, item, item%cells(i), t, factor, fext, st)
                        if (st%failed()) exit
                    end do
                case (LOAD_PRE_EPSI, LOAD_PRE_EPSI_PLATE)
                    do i = 1, size(item%cells)
                        call add_pre_epsi_forces(s, item, item%cells(i), t, factor, fext, st)
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

    !> FORCE_COQUE / PRES_REP on one plate cell: PRES (force = -PRES n) or FX/FY/FZ, known
    !> at the cell's nodes (element_loads: Code_Aster's DKT/DKQ discretisation). A PRES_REP
    !> function is refused where it is not zero, as Code_Aster refuses it on plates
    !> (message ELEMENTS4_92: a pressure function on shells goes through FORCE_COQUE).
    subroutine plate_cell_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(3, 4), q(3, 4), pres(4), fe(12), area
        integer(i4) :: nn, a, comp, p0, eq
        logical :: pressure
        if (.not. is_plate(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(item%kind)) // &
                ' applies to plate (DKT) cells, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        pressure = item%values(SLOT_PRES)%given
        q = 0.0_dp
        pres = 0.0_dp
        area = cell_measure(s%mesh, c)      ! the nodal forces are values times parts of it
        do a = 1, nn
            if (pressure) then
                call load_value_at(item%values(SLOT_PRES), item%kind, SLOT_PRES, t, x(:, a), &
                    pres(a), st)
                if (st%ok()) call check_factor(area, pres(a), item%kind, SLOT_PRES, st)
                if (st%ok()) call check_factor(factor, pres(a) * area, item%kind, SLOT_PRES, &
                                               st)
                call load_locate(item, SLOT_PRES, st)
            else
                do comp = 1, 3
                    if (item%values(comp)%given) then
                        call load_value_at(item%values(comp), item%kind, comp, t, x(:, a), &
                            q(comp, a), st)
                        if (st%ok()) call check_factor(area, q(comp, a), item%kind, comp, st)
                        if (st%ok()) call check_factor(factor, q(comp, a) * area, item%kind, &
                                                       comp, st)
                        call load_locate(item, comp, st)
                    end if
                    if (st%failed()) exit
                end do
            end if
            if (st%failed()) return
        end do
        if (item%kind == LOAD_PRES_REP .and. associated(item%values(SLOT_PRES)%func) .and. &
            any(abs(pres(1:nn)) > 0.0_dp)) then
            call set_error(st, STATUS_MODEL_ERROR, 'PRES_REP: a pressure function that ' // &
                'is not zero on plate ' // cell_label(s%mesh, c, item%group) // ' (INST ' // &
                real_e13(t) // '): Code_Aster refuses it on DKT cells (ELEMENTS4_92); ' // &
                'give it as FORCE_COQUE(PRES=...)')
            return
        end if
        if (pressure) then
            call plate_nodal_pressure(x(:, 1:nn), nn, pres(1:nn), fe(1:3 * nn), st)
        else
            call plate_nodal_forces(x(:, 1:nn), nn, q(:, 1:nn), fe(1:3 * nn), st)
        end if
        if (st%failed()) then
            call set_error(st, st%code, trim(LOAD_KIND_NAMES(item%kind)) // ' on ' // &
                cell_label(s%mesh, c, item%group) // ': ' // st%message)
            return
        end if
        do a = 1, nn
            do comp = 1, 3
                eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                if (eq > 0) fext(eq) = fext(eq) + factor * fe(3 * (a - 1) + comp)
            end do
        end do
    end subroutine plate_cell_forces

    !> FORCE_CONTOUR FX, FY (per unit length, unit depth) or PRES_REP PRES (the traction
    !> -PRES n, n the edge's normal: element_loads) on one SEG2 / SEG3 edge of a plane model,
    !> known at the edge's Gauss points.
    subroutine edge_cell_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(2, MAX_EDGE_NODES), q(2, MAX_EDGE_POINTS), fe(2 * MAX_EDGE_NODES)
        type(edge_points_t) :: pts
        integer(i4) :: g, a, comp, p0, eq, nn
        real(dp) :: pres
        if (.not. is_plane_edge(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(item%kind)) // &
                ' applies to SEG2 and SEG3 edges of a D_PLAN/C_PLAN model, not to ' // &
                cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(1:2, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call edge_load_points(s%mesh%cell_type(c), x(:, 1:nn), pts, st)
        if (st%failed()) return
        q = 0.0_dp
        do g = 1, pts%n
            if (item%kind == LOAD_PRES_REP) then
                call load_value_at(item%values(SLOT_PRES), item%kind, SLOT_PRES, t, &
                    [pts%x(1, g), pts%x(2, g), 0.0_dp], pres, st)
                if (st%ok()) call check_factor(pts%w(g), pres, item%kind, SLOT_PRES, st)
                if (st%ok()) call check_factor(factor, pres * pts%w(g), item%kind, &
                                               SLOT_PRES, st)
                call load_locate(item, SLOT_PRES, st)
                if (st%failed()) return
                q(:, g) = -pres * pts%normal(:, g)
                cycle
            end if
            do comp = 1, 2
                if (.not. item%values(comp)%given) cycle
                call load_value_at(item%values(comp), item%kind, comp, t, &
                    [pts%x(1, g), pts%x(2, g), 0.0_dp], q(comp, g), st)
                if (st%ok()) call check_factor(pts%w(g), q(comp, g), item%kind, comp, st)
                if (st%ok()) call check_factor(factor, q(comp, g) * pts%w(g), item%kind, &
                                               comp, st)
                call load_locate(item, comp, st)
                if (st%failed()) return
            end do
        end do
        call edge_line_forces(pts, q(:, 1:pts%n), fe(1:2 * nn))
        do a = 1, nn
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
