!> AFFE_CHAR_MECA LIAISON_MAIL (Code_Aster U4.44.01, validated by zzzz127): each slave node
!> (GROUP_NO_ESCL, the nodes of GROUP_MA_ESCL) is tied to the master cells (GROUP_MA_MAIT)
!> through their shape functions at the point of the master side nearest to it:
!> u(slave) = sum_i N_i(xi) u(master node i), one relation per component.
!>
!> The point is found as Code_Aster's projection (PROJ_CHAMP's pj2dco / pj4dco and pj2dtr)
!> finds it: the master cells are cut into triangles (a quadrangle 1234 into 123 and 134),
!> the node goes to the nearest point of the nearest triangle (strictly nearest: the first
!> of equals), whose barycentric coordinates give a first reference point xi1; the inverse
!> of the cell's isoparametric map at the node (in the triangle's plane) gives xi2; xi2 is
!> kept when it lies in the cell (within 1e-2 of the reference element's size) and maps
!> nearer to the node than xi1 does.
!>
!> TYPE_RACCORD:
!>  MASSIF (plane models, 2D mesh): DX, DY; with ANGL_NAUT / CENTRE / TRAN the slave node is
!>    first moved to x' = C + R (x - C) + T and its rotated displacement R u is tied to the
!>    master side at x' (zzzz127 case 1); DDL = a list of components ties those, unrotated;
!>    DDL = 'DNOR' ties the normal components n.u, n the normal of GROUP_MA_ESCL's cells at
!>    the slave node.
!>  COQUE (plates, 3D mesh): DX, DY, DZ, DRX, DRY, DRZ (or those of DDL).
!>  COQUE_MASSIF, MASSIF_COQUE tie plates to volume cells, which parasol has not: refused.
!> ELIM_MULT = 'OUI' (default): a slave node of an earlier LIAISON_MAIL occurrence of the
!> same load is not tied again (none left: Code_Aster CHARGES7_48). A slave node that is
!> itself the master node it projects on (coefficient > 0.99) gets no relation (alarm
!> CHARGES7_1). A node farther than DISTANCE_MAX from every master cell is not tied; one
!> farther than DISTANCE_ALARME (default: a tenth of the square root of the nearest
!> triangle's area) gets an alarm.
module relation_mail
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, real_e13
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, nodes_of_cells, node_name, cell_name, CELL_TRIA3, &
        CELL_TRIA6, CELL_QUAD4, CELL_QUAD8, CELL_QUAD9, CELL_TYPE_NODES, CELL_TYPE_DIM, &
        MAX_CELL_NODES
    use mesh_cell_shapes, only: cell_shape, cell_reference_nodes
    use mesh_command_support, only: relocate_error, group_cells, warn_at, read_node_groups
    use model_types, only: ELEM_NONE, is_plate, is_plane_solid
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS, DOF_DX, DOF_DY, DOF_DZ
    use model_concept, only: model_concept_t
    use model_loads, only: load_set_t, load_add_item, load_add_relation, &
        LOAD_RELATION
    use model_relations, only: node_directions, nautical_frame
    use load_occurrences, only: locate_item, three_reals
    implicit none
    private

    public :: liaison_mail_item

    !> A projected point outside its cell by more than this fraction of the reference
    !> element's size keeps the triangle's point (Code_Aster pj2dtr: disprj > 1e-2).
    real(dp), parameter :: OUTSIDE_FRACTION = 1.0e-2_dp
    !> Default alarm distance: this fraction of the square root of the nearest triangle's
    !> area (Code_Aster pj4dap).
    real(dp), parameter :: FAR_FRACTION = 1.0e-1_dp
    !> A slave node that is the master node it projects on with a coefficient within this
    !> of 1 is not tied (Code_Aster CHARGES7_1).
    real(dp), parameter :: SELF_TOLERANCE = 1.0e-2_dp
    !> Newton iterations and tolerance of the inverse isoparametric map (reference units).
    integer, parameter :: NEWTON_MAX = 20
    real(dp), parameter :: NEWTON_TOL = 1.0e-12_dp
    real(dp), parameter :: FAR_REFERENCE = 1.0e3_dp   !< |xi| past this: Newton given up
    !> Buckets per direction at most (the grid of the master cells).
    integer, parameter :: MAX_BUCKETS = 1000

    !> The master cells in a uniform grid of buckets over their bounding box (a cell in
    !> every bucket its box meets), so that a slave node looks at the cells near it first:
    !> O(slaves + cells) for a tie of matching sizes instead of O(slaves x cells).
    type :: cell_grid_t
        real(dp) :: lo(3) = 0.0_dp, h(3) = 1.0_dp
        integer :: nb(3) = 1
        integer(i4), allocatable :: ptr(:), items(:)   !< CSR: bucket -> indices in cells
        integer(i4), allocatable :: seen(:)            !< per cell: the last query that saw it
        integer(i4) :: query = 0
    end type cell_grid_t

contains

    !> One LIAISON_MAIL occurrence: its relations in a new RELATION item of `loads`.
    !>  elim : in/out, the slave nodes of earlier occurrences (ELIM_MULT)
    subroutine liaison_mail_item(ctx, occ, mc, elim, loads, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(inout) :: elim(:)
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: kind, label, answer
        type(string_t), allocatable :: ddl(:)
        integer(i4), allocatable :: masters(:), slaves(:), comps(:), skin(:)
        real(dp), allocatable :: normals(:, :)
        real(dp) :: rot(3, 3), centre(3), tran(3), dmax, dala, x(3), n(MAX_CELL_NODES), d
        real(dp) :: angles(3)
        logical :: use_normal, rotate, has_dmax
        integer(i4) :: k, s, c, nn, index, dim
        integer(i4), allocatable :: nodes(:), cs(:)   ! the relation being built (tie, add)
        real(dp), allocatable :: coefs(:)
        type(cell_grid_t) :: grid
        call occ%get_text('TYPE_RACCORD', kind, st)
        if (st%failed()) return
        if (kind == 'COQUE_MASSIF' .or. kind == 'MASSIF_COQUE') then
            call occ%error_at('TYPE_RACCORD', "TYPE_RACCORD='" // kind // "' ties plates " // &
                'to volume cells, which parasol has not (its families: DKT/DKQ plates, ' // &
                "plane solids): use 'COQUE' between plates, 'MASSIF' between plane solids", &
                st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        dim = mc%mesh%dim
        if (kind == 'COQUE' .and. dim /= 3) then
            call occ%error_at('TYPE_RACCORD', "TYPE_RACCORD='COQUE' ties plates in a 3D " // &
                "mesh; this mesh is 2D: use 'MASSIF' for plane solids", st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        if (occ%has('TRANSF_GEOM_MAIT') .or. occ%has('TRANSF_GEOM_ESCL')) then
            call occ%error_at(merge('TRANSF_GEOM_MAIT', 'TRANSF_GEOM_ESCL', &
                occ%has('TRANSF_GEOM_MAIT')), 'the geometric transformation of a side by ' // &
                'functions is not built in parasol; tie the sides where they are', st, &
                code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call master_cells(occ, mc, kind, masters, st)
        if (st%failed()) return
        call slave_nodes(occ, mc, slaves, label, st)
        if (st%failed()) return
        answer = 'OUI'
        if (occ%has('ELIM_MULT')) call occ%get_text('ELIM_MULT', answer, st)
        if (st%failed()) return
        if (answer == 'OUI') then
            slaves = pack(slaves, .not. elim(slaves))
            if (size(slaves) == 0) then
                call occ%error_at('', 'every slave node is already tied by an earlier ' // &
                    "LIAISON_MAIL occurrence (ELIM_MULT='OUI'): nothing left to tie " // &
                    '(Code_Aster CHARGES7_48)', st, code=STATUS_MODEL_ERROR)
                return
            end if
            elim(slaves) = .true.
        end if

        ! The components tied.
        use_normal = .false.
        if (occ%has('DDL')) then
            call occ%get_texts('DDL', ddl, st)
            if (st%failed()) return
            allocate (comps(0))
            do k = 1, size(ddl)
                if (ddl(k)%s == 'DNOR') then
                    if (size(ddl) > 1) then
                        call occ%error_at('DDL', "'DNOR' ties the normal component alone: " // &
                            'give it without other components (Code_Aster CHARGES7_2)', st, &
                            code=STATUS_MODEL_ERROR)
                        return
                    end if
                    use_normal = .true.
                    cycle
                end if
                if (any(comps == component_of(ddl(k)%s))) then
                    call occ%error_at('DDL', ddl(k)%s // ' is given twice', st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
                comps = [comps, component_of(ddl(k)%s)]
            end do
        else if (kind == 'COQUE') then
            comps = [(k, k = 1, N_COMPONENTS)]
        else
            comps = [DOF_DX, DOF_DY]
            if (dim == 3) comps = [comps, DOF_DZ]
        end if

        ! The slave side's move (MASSIF): x' = C + R (x - C) + T.
        rotate = occ%has('ANGL_NAUT')
        angles = 0.0_dp
        centre = 0.0_dp
        tran = 0.0_dp
        if (rotate) call three_reals(occ, 'ANGL_NAUT', angles, st)
        if (st%ok() .and. occ%has('CENTRE')) call three_reals(occ, 'CENTRE', centre, st)
        if (st%ok() .and. occ%has('TRAN')) call three_reals(occ, 'TRAN', tran, st)
        if (st%failed()) return
        if (rotate .and. dim == 2 .and. any(abs(angles(2:3)) > 0.0_dp)) then
            call occ%error_at('ANGL_NAUT', 'in a 2D mesh the rotation is about Z: give ' // &
                'one angle (the 2nd and 3rd must be 0)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call nautical_frame(angles, rot)
        rot = transpose(rot)
        if (rotate .and. use_normal) then
            call occ%error_at('ANGL_NAUT', "DDL='DNOR' with a rotation of the slave side " // &
                'is not built in parasol', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (use_normal) then
            if (.not. occ%has('GROUP_MA_ESCL')) then
                call occ%error_at('DDL', "DDL='DNOR' takes the normal of the slave cells: " // &
                    'give GROUP_MA_ESCL (Code_Aster CHARGES7_49)', st, code=STATUS_MODEL_ERROR)
                return
            end if
            call group_cells(occ, 'GROUP_MA_ESCL', mc%mesh, skin, st)
            allocate (normals(3, size(slaves)))
            if (st%ok()) call node_directions(mc%mesh, skin, slaves, .false., normals, st)
            if (st%failed()) then
                call relocate_error(occ, 'GROUP_MA_ESCL', st)
                return
            end if
        end if

        has_dmax = occ%has('DISTANCE_MAX')
        dmax = huge(1.0_dp)
        dala = -1.0_dp
        if (has_dmax) call occ%get_real('DISTANCE_MAX', dmax, st)
        if (st%ok() .and. occ%has('DISTANCE_ALARME')) call occ%get_real('DISTANCE_ALARME', &
            dala, st)
        if (st%failed()) return

        call load_add_item(loads, LOAD_RELATION, [integer(i4) ::], index, label)
        call locate_item(occ, loads, index)
        call grid_build(mc%mesh, masters, grid)
        do s = 1, size(slaves)
            x = mc%mesh%coords(:, slaves(s))
            if (rotate .or. occ%has('TRAN')) x = centre + matmul(rot, x - centre) + tran
            call project(mc%mesh, masters, grid, x, dmax, dala, c, n, d, st)
            if (st%failed()) then
                call relocate_error(occ, 'GROUP_MA_MAIT', st)
                return
            end if
            if (c == 0) cycle
            if (d > dala .and. dala >= 0.0_dp .or. d < 0.0_dp) call warn_at(ctx, occ, &
                'GROUP_MA_MAIT', 'slave node ' // node_name(mc%mesh, slaves(s)) // ' is ' // &
                real_e13(abs(d)) // ' away from the master cells (nearest ' // &
                cell_name(mc%mesh, c) // '): it is tied to the nearest point of them')
            nn = CELL_TYPE_NODES(mc%mesh%cell_type(c))
            call tie(slaves(s), mc%mesh%cell_nodes(mc%mesh%cell_ptr(c):mc%mesh%cell_ptr(c) + &
                nn - 1), n(1:nn), st)
            if (st%failed()) return
        end do

    contains

        ! The relations of slave node `sn` on the master nodes `mn` with weights `w`.
        subroutine tie(sn, mn, w, st)
            integer(i4), intent(in) :: sn, mn(:)
            real(dp), intent(in) :: w(:)
            type(status_t), intent(out) :: st
            integer(i4) :: i, j, m
            if (any(mn == sn .and. abs(w - 1.0_dp) < SELF_TOLERANCE)) then
                call warn_at(ctx, occ, 'GROUP_MA_MAIT', 'slave node ' // node_name(mc%mesh, &
                    sn) // ' is a node of the master cell it falls on: it is not tied to ' // &
                    'itself (Code_Aster CHARGES7_1)')
                return
            end if
            if (use_normal) then
                ! n.u(slave) - sum_i N_i n.u(master i) = 0 over DX..DZ (DX, DY in 2D).
                allocate (nodes(0), cs(0), coefs(0))
                do j = 1, dim
                    call add(sn, int(j, i4), normals(j, s_of(sn)), st)
                    if (st%failed()) return
                    do i = 1, size(mn)
                        call add(mn(i), int(j, i4), -w(i) * normals(j, s_of(sn)), st)
                        if (st%failed()) return
                    end do
                end do
                call load_add_relation(loads, index, nodes, cs, coefs, 0_i4, sn)
                deallocate (nodes, cs, coefs)
                return
            end if
            do m = 1, size(comps)
                allocate (nodes(0), cs(0), coefs(0))
                if (rotate .and. .not. occ%has('DDL')) then
                    ! R u(slave) = u(master side at x'), row m of R.
                    do j = 1, dim
                        call add(sn, int(j, i4), rot(comps(m), j), st)
                        if (st%failed()) return
                    end do
                else
                    call add(sn, comps(m), 1.0_dp, st)
                    if (st%failed()) return
                end if
                do i = 1, size(mn)
                    call add(mn(i), comps(m), -w(i), st)
                    if (st%failed()) return
                end do
                call load_add_relation(loads, index, nodes, cs, coefs, 0_i4, sn)
                deallocate (nodes, cs, coefs)
            end do
        end subroutine tie

        ! A term (node, component, coefficient) of the relation being built; exact zeros
        ! left out; a component the node lacks is an error.
        subroutine add(node, comp, coef, st)
            integer(i4), intent(in) :: node, comp
            real(dp), intent(in) :: coef
            type(status_t), intent(out) :: st
            if (.not. abs(coef) > 0.0_dp) return
            if (mc%dofs%equation(comp, node) <= 0) then
                call occ%error_at(merge('GROUP_MA_MAIT', 'GROUP_NO_ESCL', any(node == &
                    mc%mesh%cell_nodes(mc%mesh%cell_ptr(c):mc%mesh%cell_ptr(c + 1) - 1)) &
                    .and. .not. any(node == slaves)), 'node ' // node_name(mc%mesh, node) // &
                    ' has no component ' // trim(COMPONENT_NAMES(comp)) // ' in the ' // &
                    'model: no element carries it, a relation cannot hold it', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            nodes = [nodes, node]
            cs = [cs, comp]
            coefs = [coefs, coef]
        end subroutine add

        pure integer(i4) function s_of(node)
            integer(i4), intent(in) :: node
            integer(i4) :: q
            s_of = 0
            do q = 1, size(slaves)
                if (slaves(q) == node) s_of = q
            end do
        end function s_of
    end subroutine liaison_mail_item

    ! GROUP_MA_MAIT's cells that carry the elements of the kind of link: plates (COQUE) or
    ! plane solids (MASSIF); other cells of the groups (edges, springs) are passed over.
    subroutine master_cells(occ, mc, kind, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        character(len=*), intent(in) :: kind
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: keep(:)
        integer(i4) :: k, e
        if (.not. occ%has('GROUP_MA_MAIT')) then
            call occ%error_at('', 'LIAISON_MAIL needs the master cells: give GROUP_MA_MAIT', &
                st, code=STATUS_MODEL_ERROR)
            return
        end if
        call group_cells(occ, 'GROUP_MA_MAIT', mc%mesh, cells, st)
        if (st%failed()) return
        allocate (keep(size(cells)))
        do k = 1, size(cells)
            e = mc%model%element(cells(k))
            keep(k) = e /= ELEM_NONE .and. CELL_TYPE_DIM(mc%mesh%cell_type(cells(k))) == 2
            if (kind == 'COQUE') keep(k) = keep(k) .and. is_plate(e)
            if (kind == 'MASSIF') keep(k) = keep(k) .and. is_plane_solid(e)
        end do
        cells = pack(cells, keep)
        if (size(cells) == 0) then
            call occ%error_at('GROUP_MA_MAIT', 'no cell of these groups carries ' // &
                trim(merge('a plate (DKT/DKQ)    ', 'a plane solid element', kind == &
                'COQUE')) // " of the model: TYPE_RACCORD='" // kind // "' ties to those", &
                st, code=STATUS_MODEL_ERROR)
        end if
    end subroutine master_cells

    ! The slave nodes: those of GROUP_NO_ESCL and of GROUP_MA_ESCL's cells, distinct.
    subroutine slave_nodes(occ, mc, nodes, label, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), allocatable, intent(out) :: nodes(:)
        character(len=:), allocatable, intent(out) :: label
        type(status_t), intent(out) :: st
        logical, allocatable :: taken(:)
        integer(i4), allocatable :: cells(:), groups(:)
        type(string_t), allocatable :: names(:)
        integer(i4) :: k, g
        allocate (taken(mc%mesh%n_nodes), source=.false.)
        label = 'LIAISON_MAIL'
        if (.not. occ%has('GROUP_NO_ESCL') .and. .not. occ%has('GROUP_MA_ESCL')) then
            call occ%error_at('', 'give the slave side: GROUP_NO_ESCL or GROUP_MA_ESCL', st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        if (occ%has('GROUP_MA_ESCL')) then
            call group_cells(occ, 'GROUP_MA_ESCL', mc%mesh, cells, st)
            if (st%failed()) return
            taken(nodes_of_cells(mc%mesh, cells)) = .true.
        end if
        if (occ%has('GROUP_NO_ESCL')) then
            call read_node_groups(occ, 'GROUP_NO_ESCL', mc%mesh, names, groups, st)
            if (st%failed()) return
            do g = 1, size(groups)
                associate (m => mc%mesh)
                    do k = m%node_group_ptr(groups(g)), m%node_group_ptr(groups(g) + 1) - 1
                        taken(m%node_group_items(k)) = .true.
                    end do
                end associate
            end do
            if (size(names) > 0) label = names(1)%s
        end if
        nodes = pack([(k, k = 1, mc%mesh%n_nodes)], taken)
        if (size(nodes) == 0) then
            call occ%error_at(merge('GROUP_NO_ESCL', 'GROUP_MA_ESCL', &
                occ%has('GROUP_NO_ESCL')), 'the slave side has no node', st, &
                code=STATUS_MODEL_ERROR)
        end if
    end subroutine slave_nodes

    !> The master cell point nearest to x and the cell's shape functions there.
    !>  dmax : in, farther than this from every cell: c = 0 (not tied)
    !>  dala : in, the alarm distance (< 0: the default, a tenth of sqrt(triangle area))
    !>  c    : out, the cell (0: none within dmax)
    !>  n    : out, its shape functions at the point
    !>  d    : out, the distance; negative when beyond the default alarm distance
    subroutine project(mesh, cells, grid, x, dmax, dala, c, n, d, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        type(cell_grid_t), intent(inout) :: grid
        real(dp), intent(in) :: x(3), dmax, dala
        integer(i4), intent(out) :: c
        real(dp), intent(out) :: n(MAX_CELL_NODES), d
        type(status_t), intent(out) :: st
        integer, parameter :: SPLIT(3, 2) = reshape([1, 2, 3, 1, 3, 4], [3, 2])
        real(dp) :: xc(3, MAX_CELL_NODES), bary(3), best_bary(3), dist, area, best_area
        real(dp) :: ref(2, MAX_CELL_NODES), xi1(2), xi2(2), e1(3), e2(3), p(2)
        real(dp) :: q(2, MAX_CELL_NODES), dn(2, MAX_CELL_NODES), d1, d2, outside
        integer :: k, nn, ctype, best_t, p0, r, i1, i2, i3, b, j, ib(3), blo(3), bhi(3)
        logical :: converged
        real(dp) :: bound

        c = 0
        d = dmax
        best_t = 0
        best_area = 0.0_dp
        best_bary = 0.0_dp
        n = 0.0_dp
        ! Rings of buckets around the node's, nearest first, until no unseen cell can be
        ! nearer than the best found (a cell outside the rings searched is at least `bound`
        ! away: its box lies outside theirs).
        grid%query = grid%query + 1
        ! (clamped as reals first: a node far from the master cells stays a finite index)
        ib = int(min(max((x - grid%lo) / grid%h, 0.0_dp), real(grid%nb - 1, dp)))
        do r = 0, maxval(grid%nb)
            blo = max(ib - r, 0)
            bhi = min(ib + r, grid%nb - 1)
            do i3 = blo(3), bhi(3)
                do i2 = blo(2), bhi(2)
                    do i1 = blo(1), bhi(1)
                        if (max(abs(i1 - ib(1)), abs(i2 - ib(2)), abs(i3 - ib(3))) /= r) cycle
                        b = 1 + i1 + grid%nb(1) * (i2 + grid%nb(2) * i3)
                        do j = grid%ptr(b), grid%ptr(b + 1) - 1
                            k = grid%items(j)
                            if (grid%seen(k) == grid%query) cycle
                            grid%seen(k) = grid%query
                            call try_cell(k)
                        end do
                    end do
                end do
            end do
            bound = huge(1.0_dp)
            do j = 1, 3
                if (blo(j) > 0) bound = min(bound, x(j) - (grid%lo(j) + blo(j) * grid%h(j)))
                if (bhi(j) < grid%nb(j) - 1) bound = min(bound, &
                    grid%lo(j) + (bhi(j) + 1) * grid%h(j) - x(j))
            end do
            if (all(blo == 0) .and. all(bhi == grid%nb - 1)) exit
            if (c /= 0 .and. d < bound) exit
        end do
        if (c == 0) return
        ctype = mesh%cell_type(c)
        p0 = mesh%cell_ptr(c)
        nn = CELL_TYPE_NODES(ctype)
        xc(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(p0:p0 + nn - 1))
        call cell_reference_nodes(ctype, ref)
        xi1 = matmul(ref(:, SPLIT(:, best_t)), best_bary)
        ! The cell and the node in the plane of the triangle (e1 along its first edge).
        e1 = xc(:, SPLIT(2, best_t)) - xc(:, SPLIT(1, best_t))
        e2 = cross(e1, xc(:, SPLIT(3, best_t)) - xc(:, SPLIT(1, best_t)))
        call cell_shape(ctype, xi1(1), xi1(2), n, dn)
        ! A flat triangle (a distorted cell's half) has no plane: the triangle's point alone.
        if (.not. (norm2(e1) > 0.0_dp .and. norm2(e2) > 0.0_dp)) return
        e1 = e1 / norm2(e1)
        e2 = cross(e2 / norm2(e2), e1)
        do k = 1, nn
            q(:, k) = [dot_product(xc(:, k), e1), dot_product(xc(:, k), e2)]
        end do
        p = [dot_product(x, e1), dot_product(x, e2)]
        call inverse_map(ctype, nn, q, p, xi1, xi2, converged)
        outside = huge(1.0_dp)
        if (converged) outside = outside_measure(ctype, xi2)
        d1 = norm2(matmul(q(:, 1:nn), n(1:nn)) - p)
        if (outside <= OUTSIDE_FRACTION) then
            call cell_shape(ctype, xi2(1), xi2(2), n, dn)
            d2 = norm2(matmul(q(:, 1:nn), n(1:nn)) - p)
            if (d1 <= d2) call cell_shape(ctype, xi1(1), xi1(2), n, dn)
        end if
        if (dala < 0.0_dp .and. best_area > 0.0_dp) then
            if (d / sqrt(best_area) > FAR_FRACTION) d = -d
        end if
    contains
        ! The nearest point of master cell cells(kk)'s triangles, kept when nearer.
        subroutine try_cell(kk)
            integer, intent(in) :: kk
            integer :: tt, mm, pp, ct
            ct = mesh%cell_type(cells(kk))
            pp = mesh%cell_ptr(cells(kk))
            mm = CELL_TYPE_NODES(ct)
            xc(:, 1:mm) = mesh%coords(:, mesh%cell_nodes(pp:pp + mm - 1))
            do tt = 1, merge(1, 2, ct == CELL_TRIA3 .or. ct == CELL_TRIA6)
                call nearest_on_triangle(x, xc(:, SPLIT(1, tt)), xc(:, SPLIT(2, tt)), &
                    xc(:, SPLIT(3, tt)), bary, dist, area)
                if (dist < d) then
                    d = dist
                    c = cells(kk)
                    best_t = tt
                    best_bary = bary
                    best_area = area
                end if
            end do
        end subroutine try_cell
    end subroutine project

    ! The buckets of the master cells (cell_grid_t): about one cell per bucket, a flat
    ! direction (a plane mesh's z) one bucket thick.
    subroutine grid_build(mesh, cells, grid)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        type(cell_grid_t), intent(out) :: grid
        real(dp) :: lo(3), hi(3), clo(3, size(cells)), chi(3, size(cells)), ext(3), side
        integer(i4), allocatable :: fill(:)
        integer :: k, p0, nn, a, i1, i2, i3, b, dims, glo(3), ghi(3)
        do k = 1, size(cells)
            p0 = mesh%cell_ptr(cells(k))
            nn = CELL_TYPE_NODES(mesh%cell_type(cells(k)))
            clo(:, k) = minval(mesh%coords(:, mesh%cell_nodes(p0:p0 + nn - 1)), dim=2)
            chi(:, k) = maxval(mesh%coords(:, mesh%cell_nodes(p0:p0 + nn - 1)), dim=2)
        end do
        lo = minval(clo, dim=2)
        hi = maxval(chi, dim=2)
        ext = hi - lo
        dims = count(ext > 0.0_dp)
        side = 1.0_dp
        if (dims > 0) side = (product(ext, mask=ext > 0.0_dp) / size(cells)) ** (1.0_dp / dims)
        do a = 1, 3
            grid%nb(a) = 1
            if (ext(a) > 0.0_dp .and. side > 0.0_dp) &
                grid%nb(a) = int(min(max(ext(a) / side, 1.0_dp), real(MAX_BUCKETS, dp)))
            grid%h(a) = 1.0_dp                   ! a flat direction: one bucket, any size
            if (ext(a) > 0.0_dp) grid%h(a) = ext(a) / grid%nb(a)
        end do
        grid%lo = lo
        allocate (fill(product(grid%nb)), source=0_i4)
        do a = 1, 2
            if (a == 2) then
                allocate (grid%ptr(size(fill) + 1))
                grid%ptr(1) = 1
                do b = 1, size(fill)
                    grid%ptr(b + 1) = grid%ptr(b) + fill(b)
                end do
                allocate (grid%items(grid%ptr(size(fill) + 1) - 1))
                fill = 0
            end if
            do k = 1, size(cells)
                glo = int(min(max((clo(:, k) - lo) / grid%h, 0.0_dp), real(grid%nb - 1, dp)))
                ghi = int(min(max((chi(:, k) - lo) / grid%h, 0.0_dp), real(grid%nb - 1, dp)))
                do i3 = glo(3), ghi(3)
                    do i2 = glo(2), ghi(2)
                        do i1 = glo(1), ghi(1)
                            b = 1 + i1 + grid%nb(1) * (i2 + grid%nb(2) * i3)
                            fill(b) = fill(b) + 1
                            if (a == 2) grid%items(grid%ptr(b) + fill(b) - 1) = int(k, i4)
                        end do
                    end do
                end do
            end do
        end do
        allocate (grid%seen(size(cells)), source=0_i4)
    end subroutine grid_build

    ! The point of triangle abc nearest to x: its barycentric coordinates, the distance,
    ! and the triangle's area.
    pure subroutine nearest_on_triangle(x, a, b, c, bary, dist, area)
        real(dp), intent(in) :: x(3), a(3), b(3), c(3)
        real(dp), intent(out) :: bary(3), dist, area
        real(dp) :: ab(3), ac(3), m(2, 2), r(2), det, l(2), t, dd
        ab = b - a
        ac = c - a
        area = norm2(cross(ab, ac)) / 2.0_dp
        dist = huge(1.0_dp)
        ! Inside: the orthogonal projection onto the plane.
        m = reshape([dot_product(ab, ab), dot_product(ab, ac), dot_product(ab, ac), &
            dot_product(ac, ac)], [2, 2])
        r = [dot_product(x - a, ab), dot_product(x - a, ac)]
        det = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)
        if (det > 0.0_dp) then
            l = [m(2, 2) * r(1) - m(1, 2) * r(2), m(1, 1) * r(2) - m(2, 1) * r(1)] / det
            if (l(1) >= 0.0_dp .and. l(2) >= 0.0_dp .and. l(1) + l(2) <= 1.0_dp) then
                dist = norm2(a + l(1) * ab + l(2) * ac - x)
                bary = [1.0_dp - l(1) - l(2), l(1), l(2)]
            end if
        end if
        ! The edges ab, bc, ac.
        call on_segment(a, b, t, dd)
        if (dd < dist) then
            dist = dd
            bary = [1.0_dp - t, t, 0.0_dp]
        end if
        call on_segment(b, c, t, dd)
        if (dd < dist) then
            dist = dd
            bary = [0.0_dp, 1.0_dp - t, t]
        end if
        call on_segment(a, c, t, dd)
        if (dd < dist) then
            dist = dd
            bary = [1.0_dp - t, 0.0_dp, t]
        end if
    contains
        pure subroutine on_segment(p, q, t, dd)
            real(dp), intent(in) :: p(3), q(3)
            real(dp), intent(out) :: t, dd
            real(dp) :: pq(3), len2
            pq = q - p
            len2 = dot_product(pq, pq)
            t = 0.0_dp
            if (len2 > 0.0_dp) t = min(1.0_dp, max(0.0_dp, dot_product(x - p, pq) / len2))
            dd = norm2(p + t * pq - x)
        end subroutine on_segment
    end subroutine nearest_on_triangle

    ! Newton on x(xi) = p from xi0 (the cell's in-plane node coordinates q).
    pure subroutine inverse_map(ctype, nn, q, p, xi0, xi, converged)
        integer, intent(in) :: ctype, nn
        real(dp), intent(in) :: q(2, MAX_CELL_NODES), p(2), xi0(2)
        real(dp), intent(out) :: xi(2)
        logical, intent(out) :: converged
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), j(2, 2), r(2), det, step(2)
        integer :: it
        xi = xi0
        converged = .false.
        do it = 1, NEWTON_MAX
            call cell_shape(ctype, xi(1), xi(2), n, dn)
            r = p - matmul(q(:, 1:nn), n(1:nn))
            j = matmul(q(:, 1:nn), transpose(dn(:, 1:nn)))
            det = j(1, 1) * j(2, 2) - j(1, 2) * j(2, 1)
            if (.not. abs(det) > 0.0_dp) return
            step = [j(2, 2) * r(1) - j(1, 2) * r(2), j(1, 1) * r(2) - j(2, 1) * r(1)] / det
            xi = xi + step
            ! far outside the reference element: not this cell's point (and no overflow)
            if (.not. norm2(xi) < FAR_REFERENCE) return
            if (norm2(step) < NEWTON_TOL) then
                converged = .true.
                return
            end if
        end do
    end subroutine inverse_map

    ! How far reference point xi is outside the reference element, relative to its size
    ! (0 inside; Code_Aster pjeflo).
    pure real(dp) function outside_measure(ctype, xi) result(o)
        integer, intent(in) :: ctype
        real(dp), intent(in) :: xi(2)
        if (ctype == CELL_QUAD4 .or. ctype == CELL_QUAD8 .or. ctype == CELL_QUAD9) then
            o = max(0.0_dp, abs(xi(1)) - 1.0_dp, abs(xi(2)) - 1.0_dp) / 2.0_dp
        else
            o = max(0.0_dp, -xi(1), -xi(2), xi(1) + xi(2) - 1.0_dp)
        end if
    end function outside_measure

    pure function cross(a, b) result(v)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: v(3)
        v = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    pure integer(i4) function component_of(name) result(comp)
        character(len=*), intent(in) :: name
        integer(i4) :: k
        comp = 0
        do k = 1, N_COMPONENTS
            if (trim(COMPONENT_NAMES(k)) == trim(name)) comp = k
        end do
    end function component_of

end module relation_mail
