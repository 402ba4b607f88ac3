!> Loads of a static analysis on the original equations: which equations DDL_IMPO imposes,
!> their values at an instant, and the external force vector at an instant (FORCE_NODALE
!> at nodes; FORCE_COQUE / PRES_REP known at the plate's nodes and FORCE_CONTOUR at the
!> edge's Gauss points, as Code_Aster discretises them: element_loads, design.md "Loads").
!> Every value is multiplied by the FONC_MULT factor of its EXCIT occurrence (evaluated by
!> the caller at the instant).
module assembly_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: real_e13, to_text
    use mesh_types, only: cell_label, node_name, cell_measure
    use model_types, only: is_plate, is_plane_edge, is_plate_edge, is_plane_solid, &
        is_load_edge, is_discrete, ELEM_NONE
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS
    use model_loads, only: load_set_t, load_item_t, load_value_at, LOAD_DDL_IMPO, &
        LOAD_FORCE_NODALE, LOAD_FORCE_COQUE, LOAD_PRES_REP, LOAD_FORCE_CONTOUR, SLOT_PRES, &
        LOAD_FORCE_ARETE, LOAD_FORCE_INTERNE, LOAD_PESANTEUR, SLOT_CISA, SLOT_ANGLES, &
        PLAN_SUP, PLAN_INF, LOAD_KIND_NAMES, load_locate, load_slot_name, item_slot_name, &
        LOAD_PRE_EPSI, LOAD_PRE_EPSI_PLATE, LOAD_RELATION
    use assembly_pre_epsi, only: add_pre_epsi_forces
    use model_material, only: material_of_cell
    use model_relations, only: nautical_frame
    use number_limits, only: product_fits
    use mesh_cell_shapes, only: MAX_CELL_NODES
    use element_gauss_families, only: MAX_GAUSS_POINTS
    use element_plate, only: plate_local_frame
    use element_plate_fields, only: plate_user_turn
    use element_loads, only: plate_nodal_pressure, plate_nodal_values, edge_load_points, &
        edge_line_forces, edge_points_t, MAX_EDGE_POINTS, MAX_EDGE_NODES, area_points_t, &
        plane_load_points, area_forces
    use assembly_system, only: structure_t
    implicit none
    private

    public :: mark_imposed, impose_values, add_external_forces, check_imposed_owners, &
        record_imposed, add_follower_forces, follower_refusal

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
                        ! BLOCAGE and AFFE_CHAR_CINE skip a component the node lacks
                        ! (Code_Aster caddli; charci fills a field of every component, which
                        ! the numbering then reads where it has the equation)
                        if (eq <= 0 .and. (item%blocage .or. load%kinematic)) cycle
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
        integer(i4) :: k, i, c
        do k = 1, load%n_items
            associate (item => load%items(k))
                if (item%kind == LOAD_FORCE_NODALE) then
                    call nodal_forces(s, item, t, factor, fext, st)
                else
                    do i = 1, size(item%cells)
                        c = item%cells(i)
                        select case (item%kind)
                        case (LOAD_FORCE_COQUE)
                            call plate_cell_forces(s, item, i, t, factor, fext, st)
                        case (LOAD_PRES_REP)
                            if (is_plate(s%model%element(c))) then
                                call plate_cell_forces(s, item, i, t, factor, fext, st)
                            else
                                call edge_cell_forces(s, item, c, t, factor, fext, st)
                            end if
                        case (LOAD_FORCE_CONTOUR)
                            call edge_cell_forces(s, item, c, t, factor, fext, st)
                        case (LOAD_FORCE_ARETE)
                            call plate_edge_forces(s, item, c, t, factor, fext, st)
                        case (LOAD_FORCE_INTERNE)
                            call area_cell_forces(s, item, c, t, factor, fext, st)
                        case (LOAD_PESANTEUR)
                            call gravity_forces(s, item, c, factor, fext, st)
                        case (LOAD_PRE_EPSI, LOAD_PRE_EPSI_PLATE)
                            call add_pre_epsi_forces(s, item, c, t, factor, fext, st)
                        end select
                        if (st%failed()) exit
                    end do
                end if
            end associate
            if (st%failed()) return
        end do
    end subroutine add_external_forces

    !> The forces of a follower load set (STAT_NON_LINE EXCIT TYPE_CHARGE='SUIV') at time t
    !> on the current geometry X + u (times factor), added to fext: PRES_REP on plane edges
    !> (edge_cell_forces). Which loads may follow is checked by the analysis
    !> (follower_refusal).
    subroutine add_follower_forces(s, load, t, factor, u, fext, st)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        real(dp), intent(in) :: t, factor, u(:)
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, i
        do k = 1, load%n_items
            if (load%items(k)%kind /= LOAD_PRES_REP) cycle
            do i = 1, size(load%items(k)%cells)
                call edge_cell_forces(s, load%items(k), load%items(k)%cells(i), t, factor, &
                    fext, st, u)
                if (st%failed()) return
            end do
        end do
    end subroutine add_follower_forces

    !> Why a load set cannot be a follower load in parasol ('' when it can). Code_Aster lets
    !> FORCE_FACE, FORCE_POUTRE, PESANTEUR, ROTATION, PRES_REP, FORCE_COQUE's PRES (3D shells)
    !> and EFFE_FOND follow the geometry (its loadMecaCompute_type table; U4.51.03
    !> EXCIT/TYPE_CHARGE) and refuses the others (CHARGES8_13) and every Dirichlet load
    !> (CHARGES5: DDL_IMPO, relations, AFFE_CHAR_CINE). parasol builds PRES_REP on the edges
    !> of plane models (SEG2, SEG3); PESANTEUR, FORCE_COQUE and PRES_REP on plates are
    !> refused as not built.
    function follower_refusal(s, load) result(why)
        type(structure_t), intent(in) :: s
        type(load_set_t), intent(in) :: load
        character(len=:), allocatable :: why
        integer(i4) :: k, i
        why = ''
        if (load%kinematic) then
            why = 'a kinematic load (AFFE_CHAR_CINE) imposes values: a Dirichlet load ' // &
                'cannot follow the geometry (Code_Aster CHARGES5); give it in another ' // &
                "EXCIT occurrence with TYPE_CHARGE='FIXE_CSTE'"
            return
        end if
        do k = 1, load%n_items
            associate (item => load%items(k))
                select case (item%kind)
                case (LOAD_PRES_REP)
                    do i = 1, size(item%cells)
                        if (is_plane_edge(s%model%element(item%cells(i)))) cycle
                        why = 'PRES_REP follows the geometry on the SEG2 and SEG3 edges of ' // &
                            'D_PLAN/C_PLAN models in parasol; a follower pressure on ' // &
                            cell_label(s%mesh, item%cells(i), item%group) // ' is not built'
                        return
                    end do
                case (LOAD_DDL_IMPO, LOAD_RELATION)
                    why = trim(LOAD_KIND_NAMES(item%kind)) // ' is a Dirichlet condition: it ' // &
                        'cannot follow the geometry (Code_Aster CHARGES5); give it in a ' // &
                        "load of its own, TYPE_CHARGE='FIXE_CSTE'"
                    return
                case (LOAD_PESANTEUR, LOAD_FORCE_COQUE)
                    why = trim(LOAD_KIND_NAMES(item%kind)) // ' as a follower load is not ' // &
                        'built in parasol (PRES_REP on plane edges is)'
                    return
                case default
                    why = trim(LOAD_KIND_NAMES(item%kind)) // ' cannot follow the geometry ' // &
                        "(Code_Aster CHARGES8_13): give it with TYPE_CHARGE='FIXE_CSTE', in a " // &
                        'load of its own if it shares one with a follower pressure'
                    return
                end select
            end associate
        end do
    end function follower_refusal

    !> FORCE_NODALE at its nodes; with ANGL_NAUT the forces and moments are components in
    !> the frame of the angles (evaluated at the node), turned to global ones: f = p^T f'
    !> (model_relations nautical_frame, Code_Aster's utpvlg).
    subroutine nodal_forces(s, item, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        integer(i4) :: i, comp, eq, node
        real(dp) :: v(N_COMPONENTS), angles(3), p(3, 3)
        do i = 1, size(item%nodes)
            node = item%nodes(i)
            v = 0.0_dp
            do comp = 1, N_COMPONENTS
                if (.not. item%values(comp)%given) cycle
                call load_value_at(item%values(comp), item%kind, comp, t, &
                    s%mesh%coords(:, node), v(comp), st)
                if (st%ok()) call check_factor(factor, v(comp), item%kind, comp, st)
                call load_locate(item, comp, st)
                if (st%failed()) return
            end do
            if (item%angles) then
                do comp = 1, 3
                    call load_value_at(item%values(SLOT_ANGLES + comp - 1), item%kind, &
                        SLOT_ANGLES + comp - 1, t, s%mesh%coords(:, node), angles(comp), st)
                    call load_locate(item, SLOT_ANGLES + comp - 1, st)
                    if (st%failed()) return
                end do
                call nautical_frame(angles, p)
                v(1:3) = matmul(transpose(p), v(1:3))
                v(4:6) = matmul(transpose(p), v(4:6))
            end if
            do comp = 1, N_COMPONENTS
                if (.not. (item%values(comp)%given .or. (item%angles .and. &
                    abs(v(comp)) > 0.0_dp))) cycle
                eq = s%dofs%equation(comp, node)
                if (eq <= 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'FORCE_NODALE: node ' // &
                        node_name(s%mesh, node) // ' has no component ' // &
                        trim(COMPONENT_NAMES(comp)) // ' in the model' // trim(merge( &
                        ' (ANGL_NAUT turns the force onto it)', &
                        '                                    ', item%angles)))
                    call load_locate(item, comp, st)
                    return
                end if
                fext(eq) = fext(eq) + factor * v(comp)
            end do
        end do
    end subroutine nodal_forces

    !> FORCE_COQUE / PRES_REP on one plate cell, known at the cell's nodes (element_loads:
    !> Code_Aster's DKT/DKQ discretisation, te0032): PRES (force = -PRES n), or FX..MZ
    !> (global), or F1, F2, F3, MF1, MF2 in the cell's user frame (COQUE/ANGL_REP:
    !> element_plate_fields plate_user_turn; F3 along the cell's normal); PLAN SUP / INF
    !> moves the forces to the face at +-EPAIS/2: the moment (+-EPAIS/2) n x F is added. A
    !> PRES_REP function is refused where it is not zero, as Code_Aster refuses it on
    !> plates (message ELEMENTS4_92: a pressure function on shells goes through
    !> FORCE_COQUE).
    !>  i : in, the cell's index in item%cells (FORCE_COQUE_FO: its PRES in item%cell_pres)
    subroutine plate_cell_forces(s, item, i, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: i
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(3, 4), q(6, 4), pres(4), fe(6, 4), area, rot(3, 3), xy(2, 4), cu, su
        real(dp) :: user(3, 3), dist, fp(12)
        integer(i4) :: nn, a, comp, p0, c
        logical :: pressure
        c = item%cells(i)
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
            if (pressure .and. allocated(item%cell_pres)) then
                ! FORCE_COQUE_FO: one value per cell, evaluated at its centre (force_coque_fo)
                pres(a) = item%cell_pres(i)
                call check_factor(area, pres(a), item%kind, SLOT_PRES, st)
                if (st%ok()) call check_factor(factor, pres(a) * area, item%kind, SLOT_PRES, &
                                               st)
                call load_locate(item, SLOT_PRES, st)
            else if (pressure) then
                call load_value_at(item%values(SLOT_PRES), item%kind, SLOT_PRES, t, x(:, a), &
                    pres(a), st)
                if (st%ok()) call check_factor(area, pres(a), item%kind, SLOT_PRES, st)
                if (st%ok()) call check_factor(factor, pres(a) * area, item%kind, SLOT_PRES, &
                                               st)
                call load_locate(item, SLOT_PRES, st)
            else
                do comp = 1, 6
                    if (item%values(comp)%given) then
                        call load_value_at(item%values(comp), item%kind, comp, t, x(:, a), &
                            q(comp, a), st, slot_name=item_slot_name(item, comp))
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
            call plate_nodal_pressure(x(:, 1:nn), nn, pres(1:nn), fp(1:3 * nn), st)
            fe(1:3, 1:nn) = reshape(fp(1:3 * nn), [3, nn])
            fe(4:6, 1:nn) = 0.0_dp
        else
            call plate_local_frame(x(:, 1:nn), nn, rot, xy(:, 1:nn), st)
            if (st%ok() .and. item%local_frame) then
                ! user frame: x = c x_local + s y_local, y = n x x, the normal n
                call plate_user_turn(rot, s%cara%coque_direction(:, c), cu, su, st)
                user(:, 1) = cu * rot(1, :) + su * rot(2, :)
                user(:, 2) = -su * rot(1, :) + cu * rot(2, :)
                user(:, 3) = rot(3, :)
                do a = 1, nn
                    q(4:6, a) = matmul(user(:, 1:2), q(4:5, a))
                    q(1:3, a) = matmul(user, q(1:3, a))
                end do
            end if
            if (st%ok() .and. (item%plan == PLAN_SUP .or. item%plan == PLAN_INF)) then
                dist = 0.5_dp * s%cara%thickness(c) * merge(1.0_dp, -1.0_dp, &
                    item%plan == PLAN_SUP)
                user(:, 3) = rot(3, :)
                do a = 1, nn
                    q(4:6, a) = q(4:6, a) + dist * cross(user(:, 3), q(1:3, a))
                end do
            end if
            if (st%ok()) call plate_nodal_values(x(:, 1:nn), nn, q(:, 1:nn), fe(:, 1:nn), st)
        end if
        if (st%failed()) then
            call set_error(st, st%code, trim(LOAD_KIND_NAMES(item%kind)) // ' on ' // &
                cell_label(s%mesh, c, item%group) // ': ' // st%message)
            return
        end if
        call add_cell_forces(s, c, factor, fe(:, 1:nn), fext)
    end subroutine plate_cell_forces

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    !> FORCE_CONTOUR FX, FY or PRES_REP PRES, CISA_2D on one SEG2 / SEG3 edge of a plane
    !> model (per unit length, unit depth), evaluated at the edge's load points
    !> (element_loads): the traction of PRES_REP is -p n + c t, t = (-n_y, n_x) the tangent
    !> node 1 -> node 2 (Code_Aster nmpr2d_vect).
    !> With `u` (a follower load, STAT_NON_LINE TYPE_CHARGE='SUIV'), the points, normals and
    !> lengths are those of the current edge x = X + u (Code_Aster te0573, CHAR_MECA_PRSU),
    !> the value functions seeing X, Y at the points of the initial edge and XF, YF at the
    !> current ones; without it XF = YF = 0 (Code_Aster evalPressureSetFuncPara).
    subroutine edge_cell_forces(s, item, c, t, factor, fext, st, u)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: u(:)
        real(dp) :: x(2, MAX_EDGE_NODES), q(2, MAX_EDGE_POINTS), fe(2 * MAX_EDGE_NODES), v(2)
        real(dp) :: xf(3)
        type(edge_points_t) :: pts, pts0
        integer(i4) :: g, a, comp, p0, eq, nn, slot
        if (.not. is_plane_edge(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(item%kind)) // &
                ' applies to SEG2 and SEG3 edges of a D_PLAN/C_PLAN model, not to ' // &
                cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(1:2, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call edge_load_points(s%mesh%cell_type(c), x(:, 1:nn), pts0, st)
        if (st%failed()) return
        pts = pts0
        if (present(u)) then
            do a = 1, nn
                do comp = 1, 2
                    eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                    if (eq > 0) x(comp, a) = x(comp, a) + u(eq)
                end do
            end do
            call edge_load_points(s%mesh%cell_type(c), x(:, 1:nn), pts, st)
            if (st%failed()) then
                call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(item%kind)) // &
                    " (TYPE_CHARGE='SUIV') on " // cell_label(s%mesh, c, item%group) // &
                    ' in its current position: ' // st%message)
                return
            end if
        end if
        q = 0.0_dp
        do g = 1, pts%n
            v = 0.0_dp
            xf = 0.0_dp
            if (present(u)) xf(1:2) = pts%x(:, g)
            do comp = 1, 2
                slot = comp
                if (item%kind == LOAD_PRES_REP) slot = merge(SLOT_PRES, SLOT_CISA, comp == 1)
                if (.not. item%values(slot)%given) cycle
                call load_value_at(item%values(slot), item%kind, slot, t, &
                    [pts0%x(1, g), pts0%x(2, g), 0.0_dp], v(comp), st, x_current=xf)
                if (st%ok()) call check_factor(pts%w(g), v(comp), item%kind, slot, st)
                if (st%ok()) call check_factor(factor, v(comp) * pts%w(g), item%kind, &
                                               slot, st)
                call load_locate(item, slot, st)
                if (st%failed()) return
            end do
            if (item%kind == LOAD_PRES_REP) then
                q(1, g) = -pts%normal(1, g) * v(1) - pts%normal(2, g) * v(2)
                q(2, g) = -pts%normal(2, g) * v(1) + pts%normal(1, g) * v(2)
            else
                q(:, g) = v
            end if
        end do
        call edge_line_forces(pts, q(:, 1:pts%n), fe(1:2 * nn))
        call add_cell_forces(s, c, factor, reshape(fe(1:2 * nn), [2, nn]), fext)
    end subroutine edge_cell_forces

    !> FORCE_ARETE FX..MZ (per unit length, global) on one SEG2 edge of a DKT model: half of
    !> value x length to each node, a function evaluated at the edge's middle (Code_Aster
    !> te0034).
    subroutine plate_edge_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        real(dp) :: x(3, 2), v, length
        integer(i4) :: a, comp, p0, eq
        if (.not. is_plate_edge(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, 'FORCE_ARETE applies to SEG2 edges of a ' &
                // 'DKT model, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        x = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + 1))
        length = norm2(x(:, 2) - x(:, 1))
        do comp = 1, 6
            if (.not. item%values(comp)%given) cycle
            call load_value_at(item%values(comp), item%kind, comp, t, &
                0.5_dp * (x(:, 1) + x(:, 2)), v, st)
            if (st%ok()) call check_factor(length, v, item%kind, comp, st)
            if (st%ok()) call check_factor(factor, 0.5_dp * v * length, item%kind, comp, st)
            call load_locate(item, comp, st)
            if (st%failed()) return
            do a = 1, 2
                eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                if (eq > 0) fext(eq) = fext(eq) + factor * (0.5_dp * v * length)
            end do
        end do
    end subroutine plate_edge_forces

    !> FORCE_INTERNE FX, FY (per unit volume, unit depth) on one plane solid cell, known at
    !> the points of its RIGI family (element_loads plane_load_points; te0093 / te0094).
    subroutine area_cell_forces(s, item, c, t, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        type(area_points_t) :: pts
        real(dp) :: q(2, MAX_GAUSS_POINTS)
        integer(i4) :: g, comp
        if (.not. is_plane_solid(s%model%element(c))) then
            call set_error(st, STATUS_MODEL_ERROR, 'FORCE_INTERNE applies to D_PLAN/C_PLAN ' &
                // 'surface cells, not to ' // cell_label(s%mesh, c, item%group))
            return
        end if
        call cell_area_points(s, c, pts, st)
        if (st%failed()) then
            call set_error(st, st%code, 'FORCE_INTERNE on ' // cell_label(s%mesh, c, &
                item%group) // ': ' // st%message)
            return
        end if
        q = 0.0_dp
        do g = 1, pts%n
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
        call add_area_forces(s, c, pts, q, factor, fext)
    end subroutine area_cell_forces

    !> PESANTEUR on one cell: rho g d per unit volume, rho the ELAS RHO of its material
    !> (Code_Aster te0085 on plane solids, over the RIGI points; te0032 on plates, rho
    !> EPAIS g d per unit area with the plate's load weights). Cells without a mass take
    !> none (load edges, discretes without M_*); a discrete with a mass is refused (parasol
    !> keeps no discrete masses), as is a cell whose material has no RHO.
    subroutine gravity_forces(s, item, c, factor, fext, st)
        type(structure_t), intent(in) :: s
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: factor
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        type(area_points_t) :: pts
        real(dp) :: gd(3), rho, x(3, 4), q(6, 4), fe(6, 4), qa(2, MAX_GAUSS_POINTS)
        integer(i4) :: kind, m, nn, p0, a, comp
        kind = s%model%element(c)
        if (kind == ELEM_NONE .or. is_load_edge(kind)) return
        if (is_discrete(kind)) then
            if (s%cara%has_mass(c)) call set_error(st, STATUS_NOT_IMPLEMENTED, &
                'PESANTEUR on the discrete mass of ' // cell_label(s%mesh, c, item%group) // &
                ' is not built: parasol keeps no discrete masses (M_*: statics only)')
            call load_locate(item, 1, st)
            return
        end if
        m = material_of_cell(s%materials, c)
        if (m > 0) then
            rho = s%materials%materials(m)%elas%rho
            if (.not. s%materials%materials(m)%elas%has_rho) m = 0
        end if
        if (m == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'PESANTEUR needs the density RHO in ' // &
                'ELAS of the material of ' // cell_label(s%mesh, c, item%group))
            call load_locate(item, 1, st)
            return
        end if
        gd = [(item%values(comp)%constant, comp = 1, 3)]
        if (is_plate(kind)) then
            p0 = s%mesh%cell_ptr(c)
            nn = s%mesh%cell_ptr(c + 1) - p0
            x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
            q = 0.0_dp
            do a = 1, nn
                q(1:3, a) = rho * s%cara%thickness(c) * gd
            end do
            call plate_nodal_values(x(:, 1:nn), nn, q(:, 1:nn), fe(:, 1:nn), st)
            if (st%failed()) then
                call set_error(st, st%code, 'PESANTEUR on ' // cell_label(s%mesh, c, &
                    item%group) // ': ' // st%message)
                return
            end if
            call add_cell_forces(s, c, factor, fe(1:3, 1:nn), fext)
        else if (is_plane_solid(kind)) then
            call cell_area_points(s, c, pts, st)
            if (st%failed()) then
                call set_error(st, st%code, 'PESANTEUR on ' // cell_label(s%mesh, c, &
                    item%group) // ': ' // st%message)
                return
            end if
            ! a plane model has no Z: the Z part of gravity acts on nothing (te0085)
            do a = 1, pts%n
                qa(:, a) = rho * gd(1:2)
            end do
            call add_area_forces(s, c, pts, qa, factor, fext)
        end if
    end subroutine gravity_forces

    ! The load points of plane solid cell c (element_loads plane_load_points).
    subroutine cell_area_points(s, c, pts, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        type(area_points_t), intent(out) :: pts
        type(status_t), intent(out) :: st
        integer(i4) :: p0, nn
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        call plane_load_points(s%mesh%cell_type(c), s%mesh%coords(1:2, &
            s%mesh%cell_nodes(p0:p0 + nn - 1)), pts, st)
    end subroutine cell_area_points

    ! fext <- fext + factor times the nodal forces of q(1:2, points) on plane cell c.
    subroutine add_area_forces(s, c, pts, q, factor, fext)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        type(area_points_t), intent(in) :: pts
        real(dp), intent(in) :: q(:, :), factor
        real(dp), intent(inout) :: fext(:)
        real(dp) :: fe(2 * MAX_CELL_NODES)
        call area_forces(pts, q(:, 1:pts%n), fe(1:2 * pts%nn))
        call add_cell_forces(s, c, factor, reshape(fe(1:2 * pts%nn), [2, pts%nn]), fext)
    end subroutine add_area_forces

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

    !> fext += factor * fe: fe(comp, a) is component comp (DX, DY, DZ, DRX ... in DOF
    !> order) of the force on the a-th node of cell c; components without an equation
    !> (imposed or absent) are skipped.
    subroutine add_cell_forces(s, c, factor, fe, fext)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: factor, fe(:, :)
        real(dp), intent(inout) :: fext(:)
        integer(i4) :: a, comp, eq, p0
        p0 = s%mesh%cell_ptr(c)
        do a = 1, size(fe, 2, kind=i4)
            do comp = 1, size(fe, 1, kind=i4)
                eq = s%dofs%equation(comp, s%mesh%cell_nodes(p0 + a - 1))
                if (eq > 0) fext(eq) = fext(eq) + factor * fe(comp, a)
            end do
        end do
    end subroutine add_cell_forces

end module assembly_loads
