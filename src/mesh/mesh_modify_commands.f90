!> MODI_MAILLAGE (U4.23.04): moves a mesh (DEFORME, TRANSLATION, MODI_BASE, ROTATION,
!> SYMETRIE, ECHELLE) and orients its cells (ORIE_NORM_COQUE, ORIE_PEAU, ORIE_LIGNE), in
!> place (reuse=, as DEFI_GROUP: a model built on the mesh sees the change), in Code_Aster's
!> order (op0154): DEFORME, the transformations, ROTATION occurrences in turn, then
!> ORIE_NORM_COQUE, ORIE_PEAU and ORIE_LIGNE occurrence by occurrence, group by group.
!> DEFORME adds a displacement field's DX, DY, DZ to the nodes that carry them (vtgpld: the
!> others stay) or perturbs every node (ALEA, modi_alea). The command works on a copy: an
!> error leaves the mesh as it was. A moved mesh is checked again as LIRE_MAILLAGE checks a
!> mesh (coordinates within 1e30, no cell made degenerate: ECHELLE=0 is refused so).
module mesh_modify_commands
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: string_t, to_text
    use number_limits, only: MAX_LENGTH
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, mesh_finish, cells_of_group, cell_name, node_name
    use mesh_concept, only: mesh_concept_t
    use mesh_geometry, only: z_constant, normalized, cross
    use mesh_transform, only: translate, change_basis, rotate, reflect, scale, perturb
    use field_concept, only: field_concept_t
    use field_types, only: FIELD_NOEU, field_type_cham
    use mesh_orientation, only: orientation_report_t, orient_skin, orient_consistently, &
        orient_by_vector
    use mesh_group_keywords, only: fold_groups
    use mesh_group_commands, only: mesh_in_place
    use mesh_command_support, only: relocate_error, read_groups, group_first_node, warn_at
    implicit none
    private

    public :: run_modi_maillage, set_field_support_resolver

    !> The mesh a field's support concept (maillage, modele, result) has: DEFORME asks it of
    !> a model or a result, whose types live in layers below this one, so the composition
    !> root (command_registration) gives the procedure (field_support's mesh_of_support).
    abstract interface
        subroutine support_mesh_f(support, mesh, st)
            import :: concept_t, mesh_t, status_t
            class(concept_t), pointer, intent(in) :: support
            type(mesh_t), pointer, intent(out) :: mesh
            type(status_t), intent(out) :: st
        end subroutine support_mesh_f
    end interface
    procedure(support_mesh_f), pointer, save :: mesh_of_support => null()

    character(len=2), parameter :: DIRECTIONS(3) = ['DX', 'DY', 'DZ']

contains

    !> Gives DEFORME the mesh of a field's support (module header).
    subroutine set_field_support_resolver(resolver)
        procedure(support_mesh_f) :: resolver
        mesh_of_support => resolver
    end subroutine set_field_support_resolver

    !> MODI_MAILLAGE(reuse=MAIL, MAILLAGE=MAIL, ...). The .mess gets what each operation
    !> did (cells turned round, per group; INFO=2: their names).
    subroutine run_modi_maillage(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(mesh_concept_t), pointer :: target
        type(mesh_t) :: work
        integer(i4) :: i, info
        logical :: moved
        if (allocated(result)) deallocate (result)   ! in place: the value is MAIL itself
        call mesh_in_place(cmd, target, st)
        if (st%failed()) return
        call cmd%get_int('INFO', info, st)
        if (st%failed()) return
        work = target%mesh
        call transform(ctx, cmd, target, work, moved, st)
        if (st%failed()) return
        do i = 1, cmd%count('ORIE_NORM_COQUE')
            call orient_shells(ctx, cmd%occurrence('ORIE_NORM_COQUE', i), work, info, &
                               'ORIE_NORM_COQUE', st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('ORIE_PEAU')
            call orient_skins(ctx, cmd%occurrence('ORIE_PEAU', i), work, info, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('ORIE_LIGNE')
            call orient_shells(ctx, cmd%occurrence('ORIE_LIGNE', i), work, info, &
                               'ORIE_LIGNE', st)
            if (st%failed()) return
        end do
        target%mesh = work
    end subroutine run_modi_maillage

    ! DEFORME, TRANSLATION, MODI_BASE, ROTATION, SYMETRIE, ECHELLE, in that order; then the
    ! moved mesh checked again.
    subroutine transform(ctx, cmd, owner, mesh, moved, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_concept_t), intent(in), target :: owner
        type(mesh_t), intent(inout) :: mesh
        logical, intent(out) :: moved
        type(status_t), intent(out) :: st
        real(dp), allocatable :: values(:)
        real(dp) :: d(3), ex(3), ey(3), point(3), axis(3), angle, factor
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: last
        integer(i4) :: i
        logical :: ok
        moved = .false.
        last = ''
        if (cmd%count('DEFORME') > 0) then
            call deform(ctx, cmd%occurrence('DEFORME', 1), owner, mesh, st)
            if (st%failed()) return
            moved = .true.
            last = 'DEFORME'
        end if
        if (cmd%has('TRANSLATION')) then
            call cmd%get_reals('TRANSLATION', values, st)
            if (st%failed()) return
            d = 0.0_dp
            d(1:size(values)) = values
            call translate(mesh%coords, d)
            call ctx%write_mess('    TRANSLATION by (' // vector_text(d) // ')')
            moved = .true.
            last = 'TRANSLATION'
        end if
        if (cmd%count('MODI_BASE') > 0) then
            occ = cmd%occurrence('MODI_BASE', 1)
            call occ%get_reals('VECT_X', values, st)
            if (st%failed()) return
            d = 0.0_dp
            d(1:size(values)) = values
            call normalized(d, ex, ok)
            if (.not. ok) then
                call occ%error_at('VECT_X', 'the vector is zero (the new x axis is needed)', st)
                return
            end if
            ey = 0.0_dp
            if (size(values) == 3) then
                if (.not. occ%has('VECT_Y')) then
                    call occ%error_at('VECT_X', 'a basis in space needs VECT_Y too', st)
                    return
                end if
                call occ%get_reals('VECT_Y', values, st)
                if (st%failed()) return
                if (size(values) /= 3) then
                    call occ%error_at('VECT_Y', 'expected 3 components, as VECT_X, got ' // &
                                      to_text(size(values, kind=i4)), st)
                    return
                end if
                call normalized(values, ey, ok)
                if (.not. ok .or. abs(dot_product(ex, ey)) > 1.0e-14_dp) then
                    call occ%error_at('VECT_Y', 'VECT_X and VECT_Y must be orthogonal and ' // &
                                      'not zero (they are the new x and y axes)', st)
                    return
                end if
            end if
            call change_basis(mesh%coords, ex, ey, size(values) == 2)
            moved = .true.
            last = 'MODI_BASE'
        end if
        do i = 1, cmd%count('ROTATION')
            occ = cmd%occurrence('ROTATION', i)
            call occ%get_reals('POIN_1', values, st)
            if (st%failed()) return
            point = 0.0_dp
            point(1:size(values)) = values
            call occ%get_real('ANGLE', angle, st)
            if (st%failed()) return
            axis = [0.0_dp, 0.0_dp, 1.0_dp]
            if (size(values) == 3) then
                call rotation_axis(occ, point, axis, st)
                if (st%failed()) return
            end if
            call rotate(mesh%coords, point, axis, angle, size(values) == 2)
            call ctx%write_mess('    ROTATION by ' // to_text(angle) // ' degrees')
            moved = .true.
            last = 'ROTATION'
        end do
        if (cmd%count('SYMETRIE') > 0) then
            occ = cmd%occurrence('SYMETRIE', 1)
            call mirror_plane(ctx, occ, point, axis, st)
            if (st%failed()) return
            call reflect(mesh%coords, point, axis)
            moved = .true.
            last = 'SYMETRIE'
        end if
        if (cmd%has('ECHELLE')) then
            call cmd%get_real('ECHELLE', factor, st)
            if (st%failed()) return
            call scale(mesh%coords, factor)
            moved = .true.
            last = 'ECHELLE'
        end if
        if (.not. moved) return
        ! the moved mesh as LIRE_MAILLAGE would accept it
        if (any(.not. (abs(mesh%coords) <= MAX_LENGTH))) then
            i = findloc(any(.not. (abs(mesh%coords) <= MAX_LENGTH), dim=1), .true., dim=1)
            call cmd%error_at(last, 'node ' // node_name(mesh, i) // ' moves beyond ' // &
                to_text(MAX_LENGTH) // ' (the largest coordinate parasol accepts)', st)
            return
        end if
        call mesh_finish(mesh, 0_i4, st)
        if (st%failed()) call relocate_error(cmd, last, st)
    end subroutine transform

    ! DEFORME=_F(OPTION='TRAN', DEPL=U) or (..., ALEA=a): see the module header. U must be a
    ! NOEU_DEPL_R field on this mesh: made on the MAILLAGE itself, on a model of it, or taken
    ! from a result computed on it (a copy of its nodes), as Code_Aster's MESH1_1 asks.
    subroutine deform(ctx, occ, owner, mesh, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_concept_t), intent(in), target :: owner
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(field_concept_t), pointer :: u
        type(mesh_t), pointer :: m
        real(dp) :: alea
        integer(i4) :: j, k, c, n_moved
        integer(i4) :: cmp(3)
        logical :: same
        if (occ%has('ALEA')) then
            call occ%get_real('ALEA', alea, st)
            if (st%failed()) return
            call perturb(mesh%coords(:, 1:mesh%n_nodes), alea)
            call ctx%write_mess('    DEFORME: every node perturbed by ALEA=' // to_text(alea) &
                                // ' of the mesh''s extent')
            return
        end if
        call occ%get_concept('DEPL', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            u => p
        class default
            call occ%error_at('DEPL', 'expected a displacement field (cham_no_sdaster), ' // &
                              'got ' // p%type_name(), st)
            return
        end select
        if (u%field%location /= FIELD_NOEU .or. u%field%quantity /= 'DEPL_R') then
            call occ%error_at('DEPL', 'the field must be a NOEU_DEPL_R (displacements at ' // &
                              'the nodes); ' // u%name // ' is a ' // field_type_cham(u%field), st)
            return
        end if
        same = .false.
        if (associated(u%support)) then
            select type (s => u%support)
            type is (mesh_concept_t)
                same = associated(u%support, owner)
            class default
                if (associated(mesh_of_support)) then
                    call mesh_of_support(u%support, m, st)
                    if (st%failed()) then
                        call relocate_error(occ, 'DEPL', st)
                        return
                    end if
                    ! a model's mesh is the maillage's; a result's is a copy: same nodes
                    same = associated(m, owner%mesh)
                    if (.not. same) same = same_nodes(m, owner%mesh)
                end if
            end select
        end if
        if (same) same = size(u%field%node_values, 2) == mesh%n_nodes
        if (.not. same) then
            call occ%error_at('DEPL', 'the displacement ' // u%name // ' is on another mesh ' // &
                'than ' // owner%name // ' (make it on ' // owner%name // ', or on a ' // &
                'model or result of it)', st)
            return
        end if
        cmp = 0
        do j = 1, 3
            do c = 1, size(u%field%components, kind=i4)
                if (u%field%components(c)%s == DIRECTIONS(j)) cmp(j) = c
            end do
        end do
        n_moved = 0
        do k = 1, mesh%n_nodes
            if (.not. any(u%field%node_has(:, k))) cycle
            n_moved = n_moved + 1
            do j = 1, 3
                if (cmp(j) == 0) cycle
                if (u%field%node_has(cmp(j), k)) &
                    mesh%coords(j, k) = mesh%coords(j, k) + u%field%node_values(cmp(j), k)
            end do
        end do
        call ctx%write_mess('    DEFORME: ' // to_text(n_moved) // ' node(s) moved by ' // u%name)
    end subroutine deform

    ! A result's copy of `mesh`: the same nodes, by name (the coordinates may have moved since).
    logical function same_nodes(copy, mesh)
        type(mesh_t), intent(in) :: copy, mesh
        integer(i4) :: k
        same_nodes = copy%n_nodes == mesh%n_nodes
        if (.not. same_nodes) return
        do k = 1, mesh%n_nodes
            if (node_name(copy, k) /= node_name(mesh, k)) then
                same_nodes = .false.
                return
            end if
        end do
    end function same_nodes

    ! The unit axis of a rotation in space: DIR, or POIN_2 - POIN_1.
    subroutine rotation_axis(occ, point, axis, st)
        type(keyword_set_t), intent(in) :: occ
        real(dp), intent(in) :: point(3)
        real(dp), intent(out) :: axis(3)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: values(:)
        real(dp) :: d(3)
        character(len=:), allocatable :: key
        logical :: ok
        if (occ%has('DIR')) then
            key = 'DIR'
        else if (occ%has('POIN_2')) then
            key = 'POIN_2'
        else
            call occ%error_at('POIN_1', 'a rotation in space needs its axis: DIR or POIN_2', &
                              st)
            return
        end if
        call occ%get_reals(key, values, st)
        if (st%failed()) return
        if (size(values) /= 3) then
            call occ%error_at(key, 'expected 3 components, as POIN_1, got ' // &
                              to_text(size(values, kind=i4)), st)
            return
        end if
        d = values
        if (key == 'POIN_2') d = d - point
        call normalized(d, axis, ok)
        if (.not. ok) call occ%error_at(key, 'the axis has zero length', st)
    end subroutine rotation_axis

    ! SYMETRIE: the point and unit normal of the mirror: in the plane POINT and AXE_1 (2
    ! values each: the line; AXE_2 ignored with a warning, MESH1_63), in space POINT, AXE_1,
    ! AXE_2 (3 values each: the plane).
    subroutine mirror_plane(ctx, occ, point, normal, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        real(dp), intent(out) :: point(3), normal(3)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: p(:), a1(:), a2(:)
        real(dp) :: n(3)
        logical :: ok
        point = 0.0_dp
        call occ%get_reals('POINT', p, st)
        if (st%ok()) call occ%get_reals('AXE_1', a1, st)
        if (st%failed()) return
        if (size(a1) /= size(p)) then
            call occ%error_at('AXE_1', 'expected ' // to_text(size(p, kind=i4)) // &
                ' components, as POINT, got ' // to_text(size(a1, kind=i4)), st)
            return
        end if
        point(1:size(p)) = p
        if (size(p) == 2) then
            if (occ%has('AXE_2')) call warn_at(ctx, occ, 'AXE_2', 'ignored: in the plane the ' &
                // 'mirror is the line through POINT along AXE_1')
            n = [-a1(2), a1(1), 0.0_dp]
        else
            if (.not. occ%has('AXE_2')) then
                call occ%error_at('AXE_1', 'a mirror plane in space needs AXE_2 too', st)
                return
            end if
            call occ%get_reals('AXE_2', a2, st)
            if (st%failed()) return
            n = cross(a1, a2)
        end if
        call normalized(n, normal, ok)
        if (.not. ok) call occ%error_at('AXE_1', 'the axes do not define a mirror (zero ' // &
                                        'or parallel vectors)', st)
    end subroutine mirror_plane

    ! ORIE_NORM_COQUE (faces, or lines in the plane) / ORIE_LIGNE (lines): each group on its
    ! own, by VECT_NORM / VECT_TANG at the node of GROUP_NO (default: the first node of the
    ! first cell of the first group), else consistently with its first cell.
    subroutine orient_shells(ctx, occ, mesh, info, factor, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: info
        character(len=*), intent(in) :: factor
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), cells(:)
        type(orientation_report_t) :: report
        real(dp), allocatable :: values(:)
        real(dp) :: vector(3)
        character(len=:), allocatable :: vector_key
        integer(i4) :: g, node, n_sets
        logical :: lines
        lines = factor == 'ORIE_LIGNE'
        vector_key = merge('VECT_TANG', 'VECT_NORM', lines)
        call read_groups(occ, 'GROUP_MA', mesh, names, groups, st)
        if (st%failed()) return
        node = 0
        if (occ%has(vector_key)) then
            call occ%get_reals(vector_key, values, st)
            if (st%failed()) return
            vector = 0.0_dp
            vector(1:size(values)) = values
            if (.not. any(abs(vector) > 0.0_dp)) then
                call occ%error_at(vector_key, 'the vector is zero', st)
                return
            end if
            if (occ%has('GROUP_NO')) then
                call group_first_node(ctx, occ, 'GROUP_NO', mesh, node, st)
                if (st%failed()) return
            else
                cells = cells_of_group(mesh, groups(1))
                if (size(cells) > 0) node = mesh%cell_nodes(mesh%cell_ptr(cells(1)))
            end if
        end if
        do g = 1, size(groups, kind=i4)
            cells = cells_of_group(mesh, groups(g))
            if (node > 0) then
                call orient_by_vector(mesh, cells, node, vector, lines, report, st)
            else
                call orient_consistently(mesh, cells, lines, report, n_sets, st)
                if (st%ok() .and. n_sets > 1) call occ%error_at('GROUP_MA', 'GROUP_MA ' // &
                    names(g)%s // ' is in ' // to_text(n_sets) // ' separate pieces: each ' // &
                    'is oriented on its own, so their senses are undefined (orient them ' // &
                    'one by one, or give ' // vector_key // ')', st)
            end if
            if (st%failed()) then
                call relocate_error(occ, 'GROUP_MA', st)
                return
            end if
            call report_turned(ctx, mesh, factor, names(g)%s, size(cells, kind=i4), report, &
                               info)
        end do
    end subroutine orient_shells

    ! ORIE_PEAU: the skins of GROUP_MA_PEAU against their supports (GROUP_MA_INTERNE).
    subroutine orient_skins(ctx, occ, mesh, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: info
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), internal(:)
        type(orientation_report_t) :: report
        integer(i4) :: g
        logical :: plane
        call read_groups(occ, 'GROUP_MA_PEAU', mesh, names, groups, st)
        if (st%failed()) return
        allocate (internal(0))
        if (occ%has('GROUP_MA_INTERNE')) then
            call fold_groups(occ, 'GROUP_MA_INTERNE', mesh, .true., 'UNION', internal, st)
            if (st%failed()) return
        end if
        plane = z_constant(mesh)
        do g = 1, size(groups, kind=i4)
            call orient_skin(mesh, cells_of_group(mesh, groups(g)), internal, plane, report, st)
            if (st%failed()) then
                call relocate_error(occ, 'GROUP_MA_PEAU', st)
                return
            end if
            call report_turned(ctx, mesh, 'ORIE_PEAU', names(g)%s, &
                size(cells_of_group(mesh, groups(g)), kind=i4), report, info)
            if (report%untreated > 0) call ctx%write_mess('      ' // &
                to_text(report%untreated) // ' of them with no support cell (left as they ' &
                // 'were)')
        end do
    end subroutine orient_skins

    ! ".mess: ORIE_PEAU GROUP_MA HAUT (4 cells): 2 turned round"; INFO=2 names them.
    subroutine report_turned(ctx, mesh, factor, group, n, report, info)
        type(run_context_t), intent(inout) :: ctx
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: factor, group
        integer(i4), intent(in) :: n, info
        type(orientation_report_t), intent(in) :: report
        character(len=:), allocatable :: line
        integer(i4) :: i
        call ctx%write_mess('    ' // factor // ' GROUP_MA ' // group // ' (' // to_text(n) // &
            ' cells): ' // to_text(report%turned) // ' turned round')
        if (info < 2 .or. report%turned == 0) return
        line = '     '
        do i = 1, report%turned
            line = line // ' ' // cell_name(mesh, report%turned_cells(i))
            if (mod(i, 8) == 0 .or. i == report%turned) then
                call ctx%write_mess(line)
                line = '     '
            end if
        end do
    end subroutine report_turned

    ! "1.0, 0.0, 0.0" for the .mess.
    function vector_text(v) result(text)
        real(dp), intent(in) :: v(3)
        character(len=:), allocatable :: text
        text = to_text(v(1)) // ', ' // to_text(v(2)) // ', ' // to_text(v(3))
    end function vector_text

end module mesh_modify_commands
