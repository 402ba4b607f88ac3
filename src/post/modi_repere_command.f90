!> MODI_REPERE (Code_Aster U4.74.01, code_aster/Cata/Commands/modi_repere.py): vectors and
!> tensors of fields expressed in another frame, point by point (doc/fields.md,
!> "MODI_REPERE"), as Code_Aster's chrpno / chrpel:
!>  REPERE='UTILISATEUR'  one frame per AFFE occurrence: ANGL_NAUT (alpha, beta, gamma in
!>                        degrees; in 2D alpha alone) or VECT_X and VECT_Y (3D);
!>  REPERE='CYLINDRIQUE'  at each point, the axes (e_r, e_z, e_theta): e_z = AXE_Z (2D: the
!>                        normal to the plane), e_r the direction from ORIGINE to the point
!>                        across the axis, e_theta = e_z x e_r; a point on the axis takes the
!>                        centre of the first cell around it. Tensors then read SIXX = rr,
!>                        SIYY = zz, SIZZ = theta-theta, SIXY = r z (2D: SIXY = r theta) and
!>                        vectors DX = r, DY = z (2D vectors: the first two rows of the frame,
!>                        as Code_Aster's ut2vgl);
!> AFFE's TOUT / GROUP_MA / GROUP_NO say where each frame applies (the last occurrence at a
!> point wins; points in none keep their values). MODI_CHAM: NOM_CHAM and TYPE_CHAM
!> (VECT_2D DX DY, VECT_3D DX DY DZ (and DRX DRY DRZ), TENS_2D SIXX SIYY SIZZ SIXY (or
!> EPXX ...), TENS_3D with SIXZ SIYZ), GROUP_MA restricting the cells of an element field.
!> A node (point) lacking one of the components loses them all, as in Code_Aster. Points
!> are the nodes (NOEU, ELNO), the Gauss points of the element family (ELGA) or the cell's
!> centre (ELEM). With RESULTAT the output is a result holding the fields changed, at the
!> instants asked for (reuse: changed in place); with CHAM_GD a field.
module modi_repere_command
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cell_label, node_name, find_cell_group, cells_of_group, &
        find_node_group, nodes_of_group, cell_centre, MAX_CELL_NODES
    use model_types, only: model_t
    use field_types, only: field_t, field_component, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO
    use field_concept, only: field_concept_t
    use field_support, only: mesh_of_support, model_of_support
    use result_fields, only: result_fields_t, result_add_instant, result_put_field
    use analysis_result, only: result_concept_t
    use result_access, only: result_field_at
    use result_instants, only: selected_instants
    use element_discrete, only: nautical_rotation
    use element_gauss_families, only: gauss_rule_t, gauss_point_positions
    use field_layout, only: element_points
    use post_champ_command, only: empty_like
    implicit none
    private

    real(dp), parameter :: PI = acos(-1.0_dp)

    !> One AFFE occurrence: where, and the frame.
    type :: frame_zone_t
        logical :: cylindrical = .false.
        real(dp) :: pgl(3, 3) = 0.0_dp           !< UTILISATEUR: rows = the new axes
        real(dp) :: origin(3) = 0.0_dp, axis(3) = [0.0_dp, 0.0_dp, 1.0_dp]
        logical, allocatable :: nodes(:)         !< (n_nodes) the nodes it applies to
        logical, allocatable :: cells(:)         !< (n_cells) the cells it applies to
    end type frame_zone_t

    !> The frames of the command on a mesh.
    type :: frames_t
        type(frame_zone_t), allocatable :: zones(:)
        integer(i4) :: dim = 3
    end type frames_t

    public :: run_modi_repere

contains

    !> Handler of MODI_REPERE (registered with reuse).
    !>  st : located errors: a frame not built (COQUE ...), an ANGL_NAUT of the wrong size, a
    !>       field without the components of TYPE_CHAM, a point on the axis of CYLINDRIQUE
    !>       with no cell around it, an unknown group
    subroutine run_modi_repere(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(frames_t) :: frames
        type(field_concept_t), allocatable :: changed
        character(len=:), allocatable :: repere
        logical :: every_cell(0)
        call cmd%get_text('REPERE', repere, st)
        if (st%failed()) return
        if (repere /= 'UTILISATEUR' .and. repere /= 'CYLINDRIQUE') then
            call cmd%error_at('REPERE', 'REPERE=''' // repere // ''' is not built in ' // &
                'parasol (UTILISATEUR and CYLINDRIQUE are)', st, STATUS_MODEL_ERROR)
            return
        end if
        if (cmd%has('CHAM_GD')) then
            call cmd%get_concept('CHAM_GD', p, st)
            if (st%failed()) return
            select type (p)
            type is (field_concept_t)
                call mesh_of_support(p%support, mesh, st)
                if (st%failed()) then
                    call relocate(cmd, 'CHAM_GD', st)
                    return
                end if
                call model_of_support(p%model, model)
                if (.not. associated(model)) call model_of_support(p%support, model)
                call read_frames(cmd, repere, mesh, frames, st)
                if (st%failed()) return
                allocate (changed, source=p)
                call change_frame(p%field, guess_type(p%field, mesh%dim), mesh, model, frames, &
                    every_cell, changed%field, st)
                if (st%failed()) then
                    call relocate(cmd, 'CHAM_GD', st)
                    return
                end if
                call move_alloc(changed, result)
            class default
                call cmd%error_at('CHAM_GD', 'expected a field, got ' // p%type_name(), st)
            end select
            return
        end if
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        type is (result_concept_t)
            call read_frames(cmd, repere, p%mesh, frames, st)
            if (st%failed()) return
            model => null()
            if (p%has_structure) model => p%model
            call change_result(ctx, cmd, p, model, frames, result, st)
        class default
            call cmd%error_at('RESULTAT', 'expected a result of an analysis, got ' // &
                p%type_name(), st)
        end select
    end subroutine run_modi_repere

    ! The TYPE_CHAM of a CHAM_GD's field: a tensor when it has SIXX or EPXX, else a vector.
    function guess_type(f, dim) result(kind)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: dim
        character(len=7) :: kind
        if (field_component(f, 'SIXX') > 0 .or. field_component(f, 'EPXX') > 0) then
            kind = trim(merge('TENS_3D', 'TENS_2D', dim == 3))
        else
            kind = trim(merge('VECT_3D', 'VECT_2D', dim == 3))
        end if
    end function guess_type

    ! RESULTAT: the fields of MODI_CHAM at the instants asked for, into a new result (or
    ! the result itself with reuse).
    subroutine change_result(ctx, cmd, res, model, frames, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(result_concept_t), target, intent(inout) :: res
        type(model_t), pointer, intent(in) :: model
        type(frames_t), intent(in) :: frames
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(result_concept_t), allocatable :: out
        type(keyword_set_t) :: occ
        type(field_t), pointer :: f
        type(field_t) :: done
        integer, allocatable :: indices(:)
        integer(i4), allocatable :: at(:)
        logical, allocatable :: cells(:)
        character(len=:), allocatable :: name, kind
        logical :: by_inst, in_place
        integer :: i, k
        in_place = associated(cmd%reuse)
        call selected_instants(cmd, res, indices, by_inst, st)
        if (st%failed()) return
        allocate (at(size(indices)))
        if (.not. in_place) then
            allocate (out)
            call empty_like(res, out)
            do i = 1, size(indices)
                call result_add_instant(out, res%nume_ordre(indices(i)), res%inst(indices(i)), &
                    at(i))
            end do
        end if
        do k = 1, cmd%count('MODI_CHAM')
            occ = cmd%occurrence('MODI_CHAM', k)
            call occ%get_text('NOM_CHAM', name, st)
            if (st%ok()) call occ%get_text('TYPE_CHAM', kind, st)
            if (st%ok()) call change_cells(occ, res%mesh, cells, st)
            if (st%failed()) return
            do i = 1, size(indices)
                call result_field_at(res, int(indices(i), i4), name, f, st)
                if (st%ok()) call change_frame(f, kind, res%mesh, model, frames, cells, done, st)
                if (st%failed()) then
                    call relocate(occ, 'NOM_CHAM', st)
                    return
                end if
                if (in_place) then
                    call result_put_field(res, int(indices(i), i4), name, done)
                else
                    call result_put_field(out, at(i), name, done)
                end if
            end do
        end do
        call ctx%write_mess('    MODI_REPERE: ' // to_text(cmd%count('MODI_CHAM')) // &
            ' field(s) at ' // to_text(size(indices)) // ' instant(s)')
        if (.not. in_place) call move_alloc(out, result)
    end subroutine change_result

    ! MODI_CHAM's TOUT / GROUP_MA: the cells of an element field changed (all by default).
    subroutine change_cells(occ, mesh, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        logical, allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4) :: g, k
        allocate (cells(mesh%n_cells), source=.not. occ%has('GROUP_MA'))
        if (.not. occ%has('GROUP_MA')) return
        call occ%get_texts('GROUP_MA', names, st)
        if (st%failed()) return
        do k = 1, size(names)
            g = find_cell_group(mesh, names(k)%s, st)
            if (st%failed()) then
                call relocate(occ, 'GROUP_MA', st)
                return
            end if
            cells(cells_of_group(mesh, g)) = .true.
        end do
    end subroutine change_cells

    ! The AFFE occurrences (module header).
    subroutine read_frames(cmd, repere, mesh, frames, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: repere
        type(mesh_t), intent(in) :: mesh
        type(frames_t), intent(out) :: frames
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: names(:)
        real(dp), allocatable :: values(:), vx(:), vy(:)
        real(dp) :: angles(3), x(3), y(3), z(3)
        integer(i4) :: k, j, g
        integer(i4), allocatable :: members(:)
        frames%dim = mesh%dim
        allocate (frames%zones(cmd%count('AFFE')))
        do k = 1, size(frames%zones)
            occ = cmd%occurrence('AFFE', k)
            associate (z_ => frames%zones(k))
                z_%cylindrical = repere == 'CYLINDRIQUE'
                if (z_%cylindrical) then
                    if (occ%has('ORIGINE')) then
                        call occ%get_reals('ORIGINE', values, st)
                        if (st%failed()) return
                        if (size(values) /= mesh%dim) then
                            call occ%error_at('ORIGINE', 'ORIGINE takes ' // &
                                to_text(mesh%dim) // ' coordinates in this mesh', st, &
                                STATUS_MODEL_ERROR)
                            return
                        end if
                        z_%origin(1:mesh%dim) = values
                    end if
                    if (mesh%dim == 3) then
                        if (.not. occ%has('AXE_Z')) then
                            call occ%error_at('AXE_Z', 'CYLINDRIQUE in 3D needs AXE_Z', st, &
                                STATUS_MODEL_ERROR)
                            return
                        end if
                        call occ%get_reals('AXE_Z', values, st)
                        if (st%failed()) return
                        if (.not. norm2(values) > 0.0_dp) then
                            call occ%error_at('AXE_Z', 'AXE_Z is the zero vector', st, &
                                STATUS_MODEL_ERROR)
                            return
                        end if
                        z_%axis = values / norm2(values)
                    end if
                else if (occ%has('VECT_X')) then
                    call occ%get_reals('VECT_X', vx, st)
                    if (st%ok()) call occ%get_reals('VECT_Y', vy, st)
                    if (st%failed()) return
                    x = vx
                    y = vy
                    z = cross(x, y)
                    if (.not. (norm2(x) > 0.0_dp .and. norm2(z) > 0.0_dp)) then
                        call occ%error_at('VECT_Y', 'VECT_X and VECT_Y must be two ' // &
                            'independent vectors', st, STATUS_MODEL_ERROR)
                        return
                    end if
                    x = x / norm2(x)
                    z = z / norm2(z)
                    y = cross(z, x)
                    z_%pgl(1, :) = x
                    z_%pgl(2, :) = y
                    z_%pgl(3, :) = z
                else
                    call occ%get_reals('ANGL_NAUT', values, st)
                    if (st%failed()) return
                    if (size(values) /= merge(3, 1, mesh%dim == 3)) then
                        call occ%error_at('ANGL_NAUT', 'ANGL_NAUT takes ' // &
                            trim(merge('3 angles', '1 angle ', mesh%dim == 3)) // &
                            ' in this mesh', st, STATUS_MODEL_ERROR)
                        return
                    end if
                    angles = 0.0_dp
                    angles(1:size(values)) = values * PI / 180.0_dp
                    call nautical_rotation(angles, z_%pgl)
                end if
                allocate (z_%nodes(mesh%n_nodes), z_%cells(mesh%n_cells))
                z_%nodes = occ%has('TOUT')
                z_%cells = occ%has('TOUT')
                if (occ%has('GROUP_MA')) then
                    call occ%get_texts('GROUP_MA', names, st)
                    if (st%failed()) return
                    do j = 1, size(names)
                        g = find_cell_group(mesh, names(j)%s, st)
                        if (st%failed()) then
                            call relocate(occ, 'GROUP_MA', st)
                            return
                        end if
                        members = cells_of_group(mesh, g)
                        z_%cells(members) = .true.
                        do g = 1, size(members, kind=i4)
                            z_%nodes(mesh%cell_nodes(mesh%cell_ptr(members(g)): &
                                mesh%cell_ptr(members(g) + 1) - 1)) = .true.
                        end do
                    end do
                end if
                if (occ%has('GROUP_NO')) then
                    call occ%get_texts('GROUP_NO', names, st)
                    if (st%failed()) return
                    do j = 1, size(names)
                        g = find_node_group(mesh, names(j)%s, st)
                        if (st%failed()) then
                            call relocate(occ, 'GROUP_NO', st)
                            return
                        end if
                        z_%nodes(nodes_of_group(mesh, g)) = .true.
                    end do
                end if
            end associate
        end do
    end subroutine read_frames

    ! The field `f` in the frames (module header): `done` a copy with the TYPE_CHAM's
    ! components turned at every point the frames apply to, on the cells of `cells` (all
    ! when empty).
    subroutine change_frame(f, kind, mesh, model, frames, cells, done, st)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: kind
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        type(frames_t), intent(in) :: frames
        logical, intent(in) :: cells(:)
        type(field_t), intent(out) :: done
        type(status_t), intent(out) :: st
        integer(i4) :: cols(6), n, c, p, s, j, q, zone, node, nc
        integer(i4) :: slot(6)
        integer(i8) :: base
        real(dp) :: v(6), x(3), pgl(3, 3), pos(3, MAX_CELL_NODES)
        type(gauss_rule_t) :: rule
        logical :: have
        call component_columns(f, kind, cols, n, st)
        if (st%failed()) return
        done = f
        if (f%location == FIELD_NOEU) then
            do node = 1, f%n_nodes
                zone = zone_of_node(frames, node)
                if (zone == 0) cycle
                if (.not. all(f%node_has(cols(1:n), node))) then
                    done%node_has(cols(1:n), node) = .false.
                    cycle
                end if
                call frame_at(frames%zones(zone), mesh, mesh%coords(:, node), node, 0_i4, &
                    frames%dim, pgl, st)
                if (st%failed()) return
                v(1:n) = f%node_values(cols(1:n), node)
                call turn(kind, frames%zones(zone)%cylindrical, pgl, v(1:n))
                done%node_values(cols(1:n), node) = v(1:n)
            end do
            return
        end if
        do c = 1, f%n_cells
            if (f%n_points(c) == 0) cycle
            if (size(cells) > 0) then
                if (.not. cells(c)) cycle
            end if
            nc = size(f%sets(f%cell_set(c))%cmp, kind=i4)
            have = .true.
            do j = 1, n
                slot(j) = 0
                do q = 1, nc
                    if (f%sets(f%cell_set(c))%cmp(q) == cols(j)) slot(j) = q
                end do
                if (slot(j) == 0) have = .false.
            end do
            if (.not. have) cycle
            if (f%location == FIELD_ELGA) then
                if (.not. associated(model)) then
                    call set_error(st, STATUS_MODEL_ERROR, 'the Gauss points of the field ' // &
                        'cannot be located: its model is not known')
                    return
                end if
                call element_points(model%element(c), mesh%cell_type(c), f%n_points(c), &
                    rule, st)
                if (st%failed()) then
                    st%message = cell_label(mesh, c) // ': ' // st%message
                    return
                end if
                call gauss_point_positions(rule, mesh%coords(:, mesh%cell_nodes( &
                    mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)), pos)
            end if
            do p = 1, f%n_points(c)
                node = 0
                if (f%location == FIELD_ELNO) then
                    node = mesh%cell_nodes(mesh%cell_ptr(c) + p - 1)
                    x = mesh%coords(:, node)
                    zone = zone_of_node(frames, node)
                else if (f%location == FIELD_ELGA) then
                    x = pos(:, p)
                    zone = zone_of_cell(frames, mesh, c)
                else
                    x = cell_centre(mesh, c)
                    zone = zone_of_cell(frames, mesh, c)
                end if
                if (zone == 0) cycle
                call frame_at(frames%zones(zone), mesh, x, node, c, frames%dim, pgl, st)
                if (st%failed()) return
                do s = 1, f%n_subpoints(c)
                    base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * nc
                    v(1:n) = f%values(base + slot(1:n))
                    call turn(kind, frames%zones(zone)%cylindrical, pgl, v(1:n))
                    done%values(base + slot(1:n)) = v(1:n)
                end do
            end do
        end do
    end subroutine change_frame

    ! The components TYPE_CHAM turns, as columns of the field.
    subroutine component_columns(f, kind, cols, n, st)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: kind
        integer(i4), intent(out) :: cols(6), n
        type(status_t), intent(out) :: st
        character(len=4) :: names(6)
        integer(i4) :: j
        cols = 0
        select case (kind)
        case ('VECT_2D')
            n = 2
            names(1:2) = ['DX  ', 'DY  ']
        case ('VECT_3D')
            n = 3
            names(1:6) = ['DX  ', 'DY  ', 'DZ  ', 'DRX ', 'DRY ', 'DRZ ']
            if (field_component(f, 'DRX') > 0) n = 6
        case ('TENS_2D', 'TENS_3D')
            n = merge(4, 6, kind == 'TENS_2D')
            names = ['SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ']
            if (field_component(f, 'SIXX') == 0) names = ['EPXX', 'EPYY', 'EPZZ', 'EPXY', &
                'EPXZ', 'EPYZ']
            if (field_component(f, 'SIXX') == 0 .and. field_component(f, 'EPXX') == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'TYPE_CHAM=''' // kind // ''': the ' // &
                    'field is no tensor: it has no SIXX .. nor EPXX .. components (it has ' // &
                    join(f%components) // ')')
                return
            end if
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'TYPE_CHAM=''' // kind // ''' is not ' // &
                'built in parasol (VECT_2D, VECT_3D, TENS_2D, TENS_3D are)')
            return
        end select
        do j = 1, n
            cols(j) = field_component(f, trim(names(j)))
            if (cols(j) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'TYPE_CHAM=''' // kind // ''': the ' // &
                    'field has no component ' // trim(names(j)) // ' (' // &
                    join(f%components) // ')')
                return
            end if
        end do
    end subroutine component_columns

    ! The zone (AFFE occurrence, the last that applies) of a node, of a cell.
    pure integer(i4) function zone_of_node(frames, node) result(z)
        type(frames_t), intent(in) :: frames
        integer(i4), intent(in) :: node
        integer(i4) :: k
        z = 0
        do k = 1, size(frames%zones, kind=i4)
            if (frames%zones(k)%nodes(node)) z = k
        end do
    end function zone_of_node

    ! A cell is in a zone given by its cells, or by nodes when all its nodes are.
    pure integer(i4) function zone_of_cell(frames, mesh, c) result(z)
        type(frames_t), intent(in) :: frames
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        integer(i4) :: k
        z = 0
        do k = 1, size(frames%zones, kind=i4)
            if (frames%zones(k)%cells(c)) then
                z = k
            else if (all(frames%zones(k)%nodes(mesh%cell_nodes(mesh%cell_ptr(c): &
                mesh%cell_ptr(c + 1) - 1)))) then
                z = k
            end if
        end do
    end function zone_of_cell

    ! The frame of a zone at point x (node `node` or a point of cell `c`, 0 when not).
    subroutine frame_at(zone, mesh, x, node, c, dim, pgl, st)
        type(frame_zone_t), intent(in) :: zone
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: x(3)
        integer(i4), intent(in) :: node, c, dim
        real(dp), intent(out) :: pgl(3, 3)
        type(status_t), intent(out) :: st
        real(dp) :: er(3), scale
        integer(i4) :: k, cell
        if (.not. zone%cylindrical) then
            pgl = zone%pgl
            return
        end if
        scale = max(1.0_dp, maxval(abs(mesh%coords)))
        er = radial(x)
        if (.not. norm2(er) > 1.0e-6_dp * scale) then
            ! on the axis: the centre of the cell (of the first cell around the node)
            cell = c
            if (cell == 0) then
                do k = 1, mesh%n_cells
                    if (any(mesh%cell_nodes(mesh%cell_ptr(k):mesh%cell_ptr(k + 1) - 1) == &
                        node)) then
                        cell = k
                        exit
                    end if
                end do
            end if
            if (cell > 0) er = radial(cell_centre(mesh, cell))
            if (.not. norm2(er) > 1.0e-6_dp * scale) then
                if (node > 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'node ' // node_name(mesh, node) // &
                        ' is on the axis of the cylindrical frame and no cell around it ' // &
                        'gives a radial direction')
                else
                    call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' is on ' // &
                        'the axis of the cylindrical frame')
                end if
                return
            end if
        end if
        er = er / norm2(er)
        pgl(1, :) = er
        pgl(2, :) = zone%axis
        pgl(3, :) = cross(zone%axis, er)
        pgl(3, :) = pgl(3, :) / norm2(pgl(3, :))
    contains
        pure function radial(point) result(r)
            real(dp), intent(in) :: point(3)
            real(dp) :: r(3)
            r = point - zone%origin
            if (dim == 2) r(3) = 0.0_dp
            r = r - dot_product(r, zone%axis) * zone%axis
        end function radial
    end subroutine frame_at

    ! The components of one point in the frame pgl (rows: the new axes): tensors P T P^T,
    ! vectors P v (2D: the first two rows and columns of P).
    pure subroutine turn(kind, cylindrical, pgl, v)
        character(len=*), intent(in) :: kind
        logical, intent(in) :: cylindrical
        real(dp), intent(in) :: pgl(3, 3)
        real(dp), intent(inout) :: v(:)
        real(dp) :: t(3, 3), r(3, 3), w(6)
        select case (kind)
        case ('VECT_2D')
            v(1:2) = matmul(pgl(1:2, 1:2), v(1:2))
        case ('VECT_3D')
            v(1:3) = matmul(pgl, v(1:3))
            if (size(v) == 6) v(4:6) = matmul(pgl, v(4:6))
        case default
            t = 0.0_dp
            t(1, 1) = v(1)
            t(2, 2) = v(2)
            t(3, 3) = v(3)
            t(1, 2) = v(4)
            t(2, 1) = v(4)
            if (size(v) == 6) then
                t(1, 3) = v(5)
                t(3, 1) = v(5)
                t(2, 3) = v(6)
                t(3, 2) = v(6)
            end if
            r = matmul(pgl, matmul(t, transpose(pgl)))
            w = [r(1, 1), r(2, 2), r(3, 3), r(1, 2), r(1, 3), r(2, 3)]
            if (size(v) == 6) then
                v = w
            else if (cylindrical) then
                v = [w(1), w(2), w(3), w(5)]         ! 2D cylindrical: SIXY = r theta
            else
                v = w(1:4)
            end if
        end select
    end subroutine turn

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    pure function join(names) result(text)
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(names)
            if (k > 1) text = text // ' '
            text = text // names(k)%s
        end do
    end function join

    ! Locates a failed status at `key`.

end module modi_repere_command
