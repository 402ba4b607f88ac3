!> RIGI_PARASOL (AFFE_CARA_ELEM): spreads a global stiffness over the springs of a raft.
!>
!> Each raft cell splits its measure (area of a TRIA3/QUAD4, length of a SEG2) equally
!> among its nodes, scaled by the cell's coefficient (COEF_GROUP of its group, or
!> FONC_GROUP evaluated at the distance from the cell centre to the centre point); the
!> weight of a raft node is its share over the total, so the weights sum to 1. The spring
!> of a raft node is the discrete cell of GROUP_MA_SEG2 / GROUP_MA_POI1 that has the node
!> (for a SEG2, its node on the raft, node 1 preferred: model B springs run from ground to
!> plate); its stiffness per direction is VALE x weight (Code_Aster U4.42.01, RIGI_PARASOL).
module model_rigi_parasol
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, real_e13, string_t
    use mesh_types, only: mesh_t, cell_measure, cell_centre, cell_name, node_name, &
        cell_label, find_cell_group, find_node_group, find_node, cells_of_group, &
        nodes_of_group, CELL_POI1, CELL_SEG2
    use model_types, only: model_t, is_discrete_2d
    use model_cara_elem, only: cara_elem_t, parse_cara, parse_repere, discrete_misfit, &
        CARA_NONE, CARA_K_T_D_N, CARA_K_T_D_L, CARA_K_TR_D_N, CARA_K_TR_D_L, CARA_NAMES
    implicit none
    private

    !> The generated springs: one row per raft node.
    type, public :: rigi_parasol_table_t
        integer(i4) :: n = 0                        !< raft nodes = springs
        integer(i4) :: n_values = 0                 !< stiffness values per spring (2 or 3)
        integer(i4), allocatable :: raft_node(:)    !< (n) node number
        integer(i4), allocatable :: spring_cell(:)  !< (n) discrete cell number
        real(dp), allocatable :: weight(:)          !< (n) share / total
        real(dp), allocatable :: stiffness(:, :)    !< (n_values, n) = VALE x weight
    end type rigi_parasol_table_t

    public :: compute_rigi_parasol, apply_rigi_parasol, rigi_parasol_lines, &
        cell_centre_distances, raft_from_groups, parasol_centre

contains

    !> Distance from the centre of each cell in `cells` to `centre`, for FONC_GROUP: the
    !> caller evaluates its function at these distances to get the cell coefficients.
    function cell_centre_distances(mesh, cells, centre) result(distance)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        real(dp), intent(in) :: centre(3)
        real(dp) :: distance(size(cells))
        integer(i4) :: i
        do i = 1, size(cells)
            distance(i) = norm2(cell_centre(mesh, cells(i)) - centre)
        end do
    end function cell_centre_distances

    !> Raft cells and their coefficients from GROUP_MA names and COEF_GROUP values (one
    !> per group, or one for all groups).
    !>  st : out, STATUS_MESH_ERROR for an unknown group; STATUS_MODEL_ERROR when the number
    !>       of COEF_GROUP values is neither 1 nor the number of groups
    subroutine raft_from_groups(mesh, groups, coef_group, cells, coefficients, st)
        type(mesh_t), intent(in) :: mesh
        type(string_t), intent(in) :: groups(:)
        real(dp), intent(in) :: coef_group(:)
        integer(i4), allocatable, intent(out) :: cells(:)
        real(dp), allocatable, intent(out) :: coefficients(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: members(:)
        integer(i4) :: g
        allocate (cells(0), coefficients(0))
        if (size(coef_group) /= 1 .and. size(coef_group) /= size(groups)) then
            call set_error(st, STATUS_MODEL_ERROR, 'COEF_GROUP needs 1 value or one per ' // &
                'group (' // to_text(size(groups, kind=i4)) // '), got ' // &
                to_text(size(coef_group, kind=i4)), keyword='RIGI_PARASOL/COEF_GROUP')
            return
        end if
        do g = 1, size(groups)
            members = cells_of_group(mesh, find_cell_group(mesh, groups(g)%s, st))
            if (st%failed()) return
            cells = [cells, members]
            coefficients = [coefficients, spread(coef_group(min(g, size(coef_group))), 1, &
                                                 size(members))]
        end do
    end subroutine raft_from_groups

    !> Centre point of FONC_GROUP: NOEUD_CENTRE (node name), GROUP_NO_CENTRE (a group of
    !> one node) or COOR_CENTRE (coordinates, 2 or 3 values); exactly one must be given.
    !>  st : out, STATUS_MESH_ERROR for an unknown node or group; STATUS_MODEL_ERROR for none
    !>       or several of the three, a group of more than one node, a wrong coordinate count
    subroutine parasol_centre(mesh, centre, st, node, group, coordinates)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(out) :: centre(3)
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: node, group
        real(dp), intent(in), optional :: coordinates(:)
        integer(i4), allocatable :: nodes(:)
        centre = 0.0_dp
        if (count([present(node), present(group), present(coordinates)]) /= 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'give exactly one of NOEUD_CENTRE, ' // &
                'GROUP_NO_CENTRE, COOR_CENTRE', keyword='RIGI_PARASOL')
        else if (present(node)) then
            nodes = [find_node(mesh, node, st)]
            if (st%ok()) centre = mesh%coords(:, nodes(1))
        else if (present(group)) then
            nodes = nodes_of_group(mesh, find_node_group(mesh, group, st))
            if (st%failed()) return
            if (size(nodes) /= 1) then
                call set_error(st, STATUS_MODEL_ERROR, 'GROUP_NO_CENTRE ' // group // ' has ' &
                    // to_text(size(nodes, kind=i4)) // ' nodes, it must have one', &
                    keyword='RIGI_PARASOL/GROUP_NO_CENTRE')
                return
            end if
            centre = mesh%coords(:, nodes(1))
        else
            if (size(coordinates) < 2 .or. size(coordinates) > 3) then
                call set_error(st, STATUS_MODEL_ERROR, 'COOR_CENTRE needs 2 or 3 values', &
                               keyword='RIGI_PARASOL/COOR_CENTRE')
                return
            end if
            centre(1:size(coordinates)) = coordinates
        end if
    end subroutine parasol_centre

    !> Computes the RIGI_PARASOL springs.
    !>  raft_cells   : in, cells of GROUP_MA (all groups, concatenated)
    !>  coefficients : in, (size(raft_cells)) COEF_GROUP of each cell's group, or FONC_GROUP
    !>                 at its centre distance
    !>  spring_cells : in, cells of GROUP_MA_SEG2 / GROUP_MA_POI1
    !>  cara_name    : in, K_T_D_L (SEG2 springs) or K_T_D_N (POI1 springs)
    !>  vale         : in, KX, KY, KZ for DIS_T springs, KX, KY for 2D_DIS_T springs
    !>  table        : out, one row per raft node, in increasing node number
    !>  st           : out, STATUS_MODEL_ERROR for: unknown or misfitting CARA (K_TR_*: no
    !>                 DIS_TR), a VALE count other than 3 (3D) / 2 (2D), zero total measure,
    !>                 a spring with no node on the raft, a raft node without or with two
    !>                 springs, count mismatch
    subroutine compute_rigi_parasol(model, mesh, raft_cells, coefficients, spring_cells, &
                                    cara_name, vale, table, st, spring_group)
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: raft_cells(:), spring_cells(:)
        real(dp), intent(in) :: coefficients(:), vale(:)
        character(len=*), intent(in) :: cara_name
        type(rigi_parasol_table_t), intent(out) :: table
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: spring_group
        real(dp), allocatable :: share(:)
        real(dp) :: total
        logical, allocatable :: on_raft(:)
        integer(i4), allocatable :: spring_of(:)
        integer(i4) :: code, i, n
        code = parse_cara(cara_name)
        if (code == CARA_NONE) then
            call set_error(st, STATUS_MODEL_ERROR, 'CARA ' // cara_name // ' is not ' // &
                'supported (K_T_D_N, K_T_D_L, K_TR_D_N, K_TR_D_L)', keyword='RIGI_PARASOL/CARA')
            return
        end if
        call node_shares(mesh, raft_cells, coefficients, share, st)
        if (st%failed()) return
        allocate (on_raft(mesh%n_nodes), source=.false.)
        do i = 1, size(raft_cells)
            on_raft(mesh%cell_nodes(mesh%cell_ptr(raft_cells(i)):mesh%cell_ptr(raft_cells(i) &
                                                                             + 1) - 1)) = .true.
        end do
        call match_springs(model, mesh, on_raft, spring_cells, code, spring_of, st, &
                           spring_group)
        if (st%failed()) return
        table%n_values = 3
        if (size(spring_cells) > 0) then
            if (is_discrete_2d(model%element(spring_cells(1)))) table%n_values = 2
            if (any(is_discrete_2d(model%element(spring_cells)) .neqv. &
                    table%n_values == 2)) then
                call set_error(st, STATUS_MODEL_ERROR, 'the discretes mix DIS_T and ' // &
                    '2D_DIS_T cells: one RIGI_PARASOL needs springs of one modelisation', &
                    keyword='RIGI_PARASOL')
                return
            end if
        end if
        ! Code_Aster (acearp): a translational CARA takes KX KY KZ in 3D and KX KY in 2D.
        ! Code_Aster ignores values beyond those; parasol refuses them, so that a third
        ! value written for a 2D model (older SSNL130 B decks) is not silently dropped.
        if (size(vale) /= table%n_values) then
            call set_error(st, STATUS_MODEL_ERROR, trim(CARA_NAMES(code)) // ' on ' // &
                trim(merge('2D_DIS_T', 'DIS_T   ', table%n_values == 2)) // ' springs takes ' &
                // to_text(table%n_values) // ' values in VALE (' // &
                trim(merge('KX, KY    ', 'KX, KY, KZ', table%n_values == 2)) // '), got ' // &
                to_text(size(vale, kind=i4)), keyword='RIGI_PARASOL/VALE')
            return
        end if
        n = count(on_raft, kind=i4)
        table%n = n
        allocate (table%raft_node(n), table%spring_cell(n), table%weight(n), &
                  table%stiffness(table%n_values, n))
        total = sum(share)
        n = 0
        do i = 1, mesh%n_nodes
            if (spring_of(i) == 0) cycle
            n = n + 1
            table%raft_node(n) = i
            table%spring_cell(n) = spring_of(i)
            table%weight(n) = share(i) / total
            table%stiffness(:, n) = vale(1:table%n_values) * table%weight(n)
        end do
    end subroutine compute_rigi_parasol

    ! share(node) = sum over raft cells holding it of coefficient * measure / node count.
    subroutine node_shares(mesh, raft_cells, coefficients, share, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: raft_cells(:)
        real(dp), intent(in) :: coefficients(:)
        real(dp), allocatable, intent(out) :: share(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: i, c, p0, p1
        allocate (share(mesh%n_nodes), source=0.0_dp)
        if (size(coefficients) /= size(raft_cells)) then
            call set_error(st, STATUS_MODEL_ERROR, 'internal: one coefficient per raft cell')
            return
        end if
        do i = 1, size(raft_cells)
            c = raft_cells(i)
            if (mesh%cell_type(c) == CELL_POI1) then
                call set_error(st, STATUS_MODEL_ERROR, 'raft ' // cell_label(mesh, c) // &
                    ' is a POI1: the raft (GROUP_MA) must be surface or line cells', &
                    keyword='RIGI_PARASOL/GROUP_MA')
                return
            end if
            p0 = mesh%cell_ptr(c)
            p1 = mesh%cell_ptr(c + 1) - 1
            share(mesh%cell_nodes(p0:p1)) = share(mesh%cell_nodes(p0:p1)) &
                + coefficients(i) * cell_measure(mesh, c) / real(p1 - p0 + 1, dp)
        end do
        if (sum(share) <= 0.0_dp) call set_error(st, STATUS_MODEL_ERROR, 'the raft has ' // &
            'zero total measure (empty GROUP_MA or zero coefficients)', &
            keyword='RIGI_PARASOL/GROUP_MA')
        if (st%ok() .and. any(share < 0.0_dp)) call set_error(st, STATUS_MODEL_ERROR, &
            'a raft node has a negative share (negative COEF_GROUP / FONC_GROUP value)', &
            keyword='RIGI_PARASOL/COEF_GROUP')
    end subroutine node_shares

    ! spring_of(node) = the discrete cell of node (0 if none), for the nodes of the raft.
    subroutine match_springs(model, mesh, on_raft, spring_cells, code, spring_of, st, group)
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: on_raft(:)
        integer(i4), intent(in) :: spring_cells(:), code
        integer(i4), allocatable, intent(out) :: spring_of(:)
        type(status_t), intent(inout) :: st
        character(len=*), intent(in), optional :: group
        integer(i4) :: i, c, node, n_raft
        character(len=:), allocatable :: reason, counts
        allocate (spring_of(mesh%n_nodes), source=0_i4)
        n_raft = count(on_raft, kind=i4)
        counts = ' (' // to_text(n_raft) // ' raft nodes, ' // &
            to_text(size(spring_cells, kind=i4)) // ' discretes)'
        if (code == CARA_K_TR_D_N .or. code == CARA_K_TR_D_L) then
            ! the catalog takes them; the raft's rotational stiffnesses are not built
            reason = ''
            if (size(spring_cells) > 0) reason = discrete_misfit(model, mesh, &
                spring_cells(1), code, 'RIGI_PARASOL', group)
            if (len(reason) == 0) reason = 'RIGI_PARASOL ' // trim(CARA_NAMES(code)) // &
                ' (the rotational stiffnesses of the raft on DIS_TR springs) is not built' &
                // '; use K_T_D_N or K_T_D_L on DIS_T springs'
            call set_error(st, merge(STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED, &
                index(reason, ' is not built') == 0), reason, keyword='RIGI_PARASOL/CARA')
            return
        end if
        do i = 1, size(spring_cells)
            c = spring_cells(i)
            reason = discrete_misfit(model, mesh, c, code, 'RIGI_PARASOL', group)
            if (len(reason) > 0) then
                call set_error(st, STATUS_MODEL_ERROR, reason, keyword='RIGI_PARASOL/CARA')
                return
            end if
            node = mesh%cell_nodes(mesh%cell_ptr(c))
            if (.not. on_raft(node) .and. mesh%cell_type(c) == CELL_SEG2) &
                node = mesh%cell_nodes(mesh%cell_ptr(c) + 1)
            if (.not. on_raft(node)) then
                call set_error(st, STATUS_MODEL_ERROR, 'discrete ' // cell_label(mesh, c, &
                    group) // ' has no node on the raft' // counts, keyword='RIGI_PARASOL')
                return
            end if
            if (spring_of(node) /= 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'raft node ' // node_name(mesh, node) &
                    // ' has two discretes, ' // cell_name(mesh, spring_of(node)) // ' and ' &
                    // cell_name(mesh, c) // counts, keyword='RIGI_PARASOL')
                return
            end if
            spring_of(node) = c
        end do
        do node = 1, mesh%n_nodes
            if (on_raft(node) .and. spring_of(node) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'raft node ' // node_name(mesh, node) &
                    // ' has no discrete in the spring group' // counts, keyword='RIGI_PARASOL')
                return
            end if
        end do
        if (code /= CARA_K_T_D_N .and. code /= CARA_K_T_D_L) call set_error(st, &
            STATUS_MODEL_ERROR, 'internal: misfit not detected', keyword='RIGI_PARASOL')
    end subroutine match_springs

    !> Stores the table's springs in `cara` as DISCRET values with CARA `cara_name` and
    !> REPERE `repere` ('GLOBAL' | 'LOCAL'). Errors: unknown REPERE.
    subroutine apply_rigi_parasol(cara, table, cara_name, repere, st)
        type(cara_elem_t), intent(inout) :: cara
        type(rigi_parasol_table_t), intent(in) :: table
        character(len=*), intent(in) :: cara_name, repere
        type(status_t), intent(out) :: st
        integer(i4) :: k, c
        if (parse_repere(repere) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'REPERE ' // repere // ' is not ' // &
                'supported (GLOBAL, LOCAL)', keyword='RIGI_PARASOL/REPERE')
            return
        end if
        do k = 1, table%n
            c = table%spring_cell(k)
            cara%discrete_cara(c) = parse_cara(cara_name)
            cara%discrete_repere(c) = parse_repere(repere)
            cara%discrete_values(:, c) = 0.0_dp
            cara%discrete_values(1:table%n_values, c) = table%stiffness(:, k)
            cara%discrete_matrix(c) = 0
        end do
    end subroutine apply_rigi_parasol

    !> INFO=2 listing: `RIGI_PARASOL <cell> <node> <weight> <k1> <k2> [<k3>]` per spring
    !> (reals in real_e13 format), then `RIGI_PARASOL SUM_OF_WEIGHTS <sum>`.
    function rigi_parasol_lines(mesh, table) result(lines)
        type(mesh_t), intent(in) :: mesh
        type(rigi_parasol_table_t), intent(in) :: table
        character(len=120), allocatable :: lines(:)
        integer(i4) :: k, j
        character(len=:), allocatable :: text
        allocate (lines(table%n + 1))
        do k = 1, table%n
            text = 'RIGI_PARASOL ' // cell_name(mesh, table%spring_cell(k)) // ' ' // &
                node_name(mesh, table%raft_node(k)) // ' ' // real_e13(table%weight(k))
            do j = 1, table%n_values
                text = text // ' ' // real_e13(table%stiffness(j, k))
            end do
            lines(k) = text
        end do
        lines(table%n + 1) = 'RIGI_PARASOL SUM_OF_WEIGHTS ' // real_e13(sum(table%weight))
    end function rigi_parasol_lines

end module model_rigi_parasol
