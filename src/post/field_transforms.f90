!> Fields made from other fields, as Code_Aster's CALC_CHAMP makes them (doc/fields.md):
!>  gauss_to_nodes  ELGA -> ELNO: each cell's Gauss values extrapolated to its nodes, sub-point
!>                  by sub-point, by element_gauss_families' matrix of the element family
!>                  the points are (Code_Aster's inmat4-6, R3.06.03): points that are the
!>                  nodes (discrete springs, RIGI=NOEU) copied, one point given to every
!>                  node, otherwise the corners the least-squares fit of the linear shape
!>                  functions (exact when the points are as many as the corners: DKQ and
!>                  plane QUAD4 FPG4, DKT FPG3), side-middle nodes the mean of their two
!>                  corners, a QUAD9 centre the mean of its four;
!>  nodes_average   ELNO -> NOEU: at each node the mean of the values the cells around it
!>                  give (Code_Aster's arithmetic mean), a component where some cell gives
!>                  it; a field with sub-points (plate layers) must first be reduced to one
!>                  (POST_CHAMP EXTR_COQUE);
!>  equivalent_stresses  SIEQ (VMIS TRESCA PRIN_1 PRIN_2 PRIN_3 VMIS_SG VECT_1_X ...
!>                  VECT_3_Z TRSIG TRIAX) and equivalent_strains EPEQ (INVA_2 PRIN_1..3
!>                  INVA_2SG VECT_*) point by point (Code_Aster fgequi: principal values in
!>                  increasing order).
module field_transforms
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use deck_catalog, only: split_words
    use mesh_types, only: mesh_t, cell_label, MAX_CELL_NODES
    use model_types, only: model_t
    use element_gauss_families, only: gauss_rule_t, MAX_GAUSS_POINTS, &
        rule_to_nodes => gauss_to_nodes
    use field_layout, only: element_points
    use field_types, only: field_t, component_set_t, field_init_cells, field_init_nodes, &
        field_define_cells, field_component, FIELD_ELNO, FIELD_NOEU
    implicit none
    private

    character(len=*), parameter, public :: SIEQ_CMPS = 'VMIS TRESCA PRIN_1 PRIN_2 PRIN_3 ' // &
        'VMIS_SG VECT_1_X VECT_1_Y VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y ' // &
        'VECT_3_Z TRSIG TRIAX'
    character(len=*), parameter, public :: EPEQ_CMPS = 'INVA_2 PRIN_1 PRIN_2 PRIN_3 ' // &
        'INVA_2SG VECT_1_X VECT_1_Y VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y ' // &
        'VECT_3_Z'

    public :: gauss_to_nodes, nodes_average, equivalent_field, symmetric_eigen

contains

    !> The extrapolation matrix e(node, point) of a cell (module header): the points are
    !> those of the element family with as many points (field_layout element_points).
    !>  st : STATUS_MODEL_ERROR naming the cell when no family has that many points
    subroutine extrapolation_matrix(mesh, model, c, ng, e, nn, st)
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        integer(i4), intent(in) :: c, ng
        real(dp), intent(out) :: e(MAX_CELL_NODES, MAX_GAUSS_POINTS)
        integer(i4), intent(out) :: nn
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        e = 0.0_dp
        nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        call element_points(model%element(c), mesh%cell_type(c), ng, rule, st)
        if (st%ok()) call rule_to_nodes(rule, e(1:nn, 1:ng), st)
        if (st%failed()) st%message = cell_label(mesh, c) // ': ' // st%message
    end subroutine extrapolation_matrix

    !> ELGA -> ELNO (module header): the field `fe` of the same quantity and components.
    !>  st : a cell whose points cannot be extrapolated (named)
    subroutine gauss_to_nodes(fg, mesh, model, fe, st)
        type(field_t), intent(in) :: fg
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        type(field_t), intent(out) :: fe
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:)
        real(dp) :: e(MAX_CELL_NODES, MAX_GAUSS_POINTS)
        integer(i4) :: c, nn, ng, n_sub, n_cmp, node, p, j, a, b
        integer(i8) :: base_in, base_out
        ! the matrices made so far, by (element, cell type, points): a matrix depends on
        ! nothing else, and making it (the element's families, a least-squares fit) cost
        ! more than extrapolating (doc/performance.md, "CALC_CHAMP")
        integer(i4), parameter :: MAX_KEPT = 16
        real(dp) :: kept(MAX_CELL_NODES, MAX_GAUSS_POINTS, MAX_KEPT)
        integer(i4) :: kept_key(4, MAX_KEPT), n_kept, key(3), hit, stride
        real(dp) :: total
        call field_init_cells(fe, FIELD_ELNO, fg%quantity, fg%components, fg%n_cells, st)
        if (st%failed()) return
        allocate (n_points(fg%n_cells), source=0_i4)
        do c = 1, fg%n_cells
            if (fg%n_points(c) > 0) n_points(c) = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        end do
        call field_define_cells(fe, n_points, fg%n_subpoints, fg%cell_set, fg%sets, st)
        if (st%failed()) return
        n_kept = 0
        do c = 1, fg%n_cells
            ng = fg%n_points(c)
            if (ng == 0) cycle
            key = [model%element(c), mesh%cell_type(c), ng]
            hit = 0
            do j = 1, n_kept
                if (all(kept_key(1:3, j) == key)) then
                    hit = j
                    exit
                end if
            end do
            if (hit > 0) then
                e = kept(:, :, hit)
                nn = kept_key(4, hit)
            else
                call extrapolation_matrix(mesh, model, c, ng, e, nn, st)
                if (st%failed()) return
                if (n_kept < MAX_KEPT) then
                    n_kept = n_kept + 1
                    kept(:, :, n_kept) = e
                    kept_key(:, n_kept) = [key, nn]
                end if
            end if
            n_sub = fg%n_subpoints(c)
            n_cmp = size(fg%sets(fg%cell_set(c))%cmp, kind=i4)
            base_in = fg%offset(c)
            base_out = fe%offset(c)
            ! each value: the sum over the points p = 1, 2, ... in turn
            stride = n_sub * n_cmp
            do node = 1, nn
                do b = 1, stride
                    total = 0.0_dp
                    a = b
                    do p = 1, ng
                        total = total + e(node, p) * fg%values(base_in + a)
                        a = a + stride
                    end do
                    fe%values(base_out + (node - 1) * stride + b) = total
                end do
            end do
        end do
    end subroutine gauss_to_nodes

    !> ELNO -> NOEU (module header).
    !>  st : STATUS_MODEL_ERROR for a field with several sub-points on a cell
    subroutine nodes_average(fe, mesh, fn, st)
        type(field_t), intent(in) :: fe
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(out) :: fn
        type(status_t), intent(out) :: st
        real(dp), allocatable :: total(:, :)
        integer(i4), allocatable :: count(:, :)
        integer(i4) :: c, p, j, n_cmp, node, k
        do c = 1, fe%n_cells
            if (fe%n_points(c) > 0 .and. fe%n_subpoints(c) > 1) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' has ' // &
                    to_text(fe%n_subpoints(c)) // ' sub-points (plate layers): a field at ' // &
                    'the nodes takes one; extract a layer and level first (POST_CHAMP ' // &
                    'EXTR_COQUE)')
                return
            end if
        end do
        allocate (total(size(fe%components), mesh%n_nodes), source=0.0_dp)
        allocate (count(size(fe%components), mesh%n_nodes), source=0_i4)
        do c = 1, fe%n_cells
            if (fe%n_points(c) == 0) cycle
            associate (cmps => fe%sets(fe%cell_set(c))%cmp)
                n_cmp = size(cmps, kind=i4)
                do p = 1, fe%n_points(c)
                    node = mesh%cell_nodes(mesh%cell_ptr(c) + p - 1)
                    do j = 1, n_cmp
                        k = cmps(j)
                        total(k, node) = total(k, node) + fe%values(fe%offset(c) + &
                            (p - 1) * n_cmp + j)
                        count(k, node) = count(k, node) + 1
                    end do
                end do
            end associate
        end do
        call field_init_nodes(fn, fe%quantity, fe%components, mesh%n_nodes, st)
        if (st%failed()) return
        fn%node_has = count > 0
        where (count > 0) fn%node_values = total / real(max(count, 1_i4), dp)
    end subroutine nodes_average

    !> SIEQ (stresses) or EPEQ (strains) of a field of SIXX.. / EPXX.. components, at the
    !> same points and sub-points (module header).
    !>  kind : in, 'SIGM' or 'EPSI';  f : in, the tensors (components of the 6 absent are 0)
    !>  st   : STATUS_MODEL_ERROR when the field has none of the tensor's components
    subroutine equivalent_field(f, kind, out, st)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: kind
        type(field_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        character(len=4), parameter :: SIG(6) = ['SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ']
        character(len=4), parameter :: EPS(6) = ['EPXX', 'EPYY', 'EPZZ', 'EPXY', 'EPXZ', 'EPYZ']
        integer(i4) :: cols(6), c, p, s, j, n_cmp, n_out
        integer(i4), allocatable :: out_sets(:)
        type(component_set_t), allocatable :: sets(:)
        real(dp) :: t(6), eq(17)
        integer(i8) :: base
        logical :: stress
        stress = kind == 'SIGM'
        do j = 1, 6
            if (stress) then
                cols(j) = field_component(f, SIG(j))
            else
                cols(j) = field_component(f, EPS(j))
            end if
        end do
        if (all(cols == 0)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field has no ' // &
                trim(merge('stress', 'strain', stress)) // ' tensor components')
            return
        end if
        if (stress) then
            call split_words(SIEQ_CMPS, names)
        else
            call split_words(EPEQ_CMPS, names)
        end if
        n_out = size(names, kind=i4)
        if (f%location == FIELD_NOEU) then
            call field_init_nodes(out, trim(merge('SIEF_R', 'EPSI_R', stress)), names, &
                f%n_nodes, st)
            if (st%failed()) return
            do p = 1, f%n_nodes
                if (.not. any(f%node_has(pack(cols, cols > 0), p))) cycle
                t = 0.0_dp
                do j = 1, 6
                    if (cols(j) > 0) t(j) = f%node_values(cols(j), p)
                end do
                call equivalents(t, stress, eq)
                out%node_values(:, p) = eq(1:n_out)
                out%node_has(:, p) = .true.
            end do
            return
        end if
        call field_init_cells(out, f%location, trim(merge('SIEF_R', 'EPSI_R', stress)), &
            names, f%n_cells, st)
        if (st%failed()) return
        allocate (sets(1), out_sets(f%n_cells))
        sets(1)%cmp = [(j, j = 1, n_out)]
        out_sets = merge(1_i4, 0_i4, f%n_points > 0)
        call field_define_cells(out, f%n_points, f%n_subpoints, out_sets, sets, st)
        if (st%failed()) return
        do c = 1, f%n_cells
            if (f%n_points(c) == 0) cycle
            n_cmp = size(f%sets(f%cell_set(c))%cmp, kind=i4)
            do p = 1, f%n_points(c)
                do s = 1, f%n_subpoints(c)
                    base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * n_cmp
                    t = 0.0_dp
                    do j = 1, 6
                        if (cols(j) == 0) cycle
                        k_loop: block
                            integer(i4) :: q
                            do q = 1, n_cmp
                                if (f%sets(f%cell_set(c))%cmp(q) == cols(j)) then
                                    t(j) = f%values(base + q)
                                    exit
                                end if
                            end do
                        end block k_loop
                    end do
                    call equivalents(t, stress, eq)
                    base = out%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * n_out
                    out%values(base + 1:base + n_out) = eq(1:n_out)
                end do
            end do
        end do
    end subroutine equivalent_field

    !> Equivalent values of a symmetric tensor (xx yy zz xy xz yz): stresses (17 values:
    !> VMIS TRESCA PRIN_1..3 VMIS_SG VECT_1_X..VECT_3_Z TRSIG TRIAX) or strains (14: INVA_2
    !> PRIN_1..3 INVA_2SG VECT_*), Code_Aster's fgequi.
    pure subroutine equivalents(t, stress, eq)
        real(dp), intent(in) :: t(6)
        logical, intent(in) :: stress
        real(dp), intent(out) :: eq(17)
        real(dp) :: a(3, 3), values(3), vectors(3, 3), hyd, dev(6), norm2dev
        integer(i4) :: i
        eq = 0.0_dp
        a(1, :) = [t(1), t(4), t(5)]
        a(2, :) = [t(4), t(2), t(6)]
        a(3, :) = [t(5), t(6), t(3)]
        call symmetric_eigen(a, values, vectors)
        hyd = (t(1) + t(2) + t(3)) / 3.0_dp
        dev = [t(1) - hyd, t(2) - hyd, t(3) - hyd, t(4), t(5), t(6)]
        norm2dev = dev(1)**2 + dev(2)**2 + dev(3)**2 + 2.0_dp * (dev(4)**2 + dev(5)**2 + &
            dev(6)**2)
        if (stress) then
            eq(1) = sqrt(1.5_dp * norm2dev)
            eq(3:5) = values
            eq(2) = max(abs(values(1) - values(2)), abs(values(1) - values(3)), &
                abs(values(2) - values(3)))
            eq(6) = merge(eq(1), -eq(1), hyd >= 0.0_dp)
            do i = 1, 3
                eq(6 + 3 * (i - 1) + 1:6 + 3 * i) = vectors(:, i)
            end do
            eq(16) = 3.0_dp * hyd
            if (eq(1) > 1.0e-10_dp * abs(eq(16))) eq(17) = hyd / eq(1)
        else
            eq(1) = sqrt(2.0_dp / 3.0_dp * norm2dev)
            eq(2:4) = values
            eq(5) = merge(eq(1), -eq(1), hyd >= 0.0_dp)
            do i = 1, 3
                eq(5 + 3 * (i - 1) + 1:5 + 3 * i) = vectors(:, i)
            end do
        end if
    end subroutine equivalents

    !> Eigenvalues (increasing) and unit eigenvectors (columns) of a symmetric 3x3 matrix,
    !> by cyclic Jacobi rotations (converged to round-off).
    pure subroutine symmetric_eigen(a0, values, vectors)
        real(dp), intent(in) :: a0(3, 3)
        real(dp), intent(out) :: values(3), vectors(3, 3)
        real(dp) :: a(3, 3), theta, t, c, s, tau, apq, app, aqq, rot(3, 3), tmp(3)
        integer(i4) :: sweep, p, q, i, k
        a = a0
        vectors = 0.0_dp
        do i = 1, 3
            vectors(i, i) = 1.0_dp
        end do
        do sweep = 1, 50
            if (abs(a(1, 2)) + abs(a(1, 3)) + abs(a(2, 3)) <= tiny(1.0_dp)) exit
            do p = 1, 2
                do q = p + 1, 3
                    apq = a(p, q)
                    app = a(p, p)
                    aqq = a(q, q)
                    ! an off-diagonal term below round-off of the diagonal is zero
                    if (.not. abs(apq) > 1.0e-3_dp * epsilon(1.0_dp) * (abs(app) + &
                        abs(aqq))) then
                        a(p, q) = 0.0_dp
                        a(q, p) = 0.0_dp
                        cycle
                    end if
                    theta = (aqq - app) / (2.0_dp * apq)
                    if (abs(theta) > 1.0e150_dp) then
                        t = 0.5_dp / theta
                    else
                        t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta * theta + 1.0_dp))
                    end if
                    c = 1.0_dp / sqrt(t * t + 1.0_dp)
                    s = t * c
                    rot = 0.0_dp
                    do i = 1, 3
                        rot(i, i) = 1.0_dp
                    end do
                    rot(p, p) = c
                    rot(q, q) = c
                    rot(p, q) = s
                    rot(q, p) = -s
                    a = matmul(transpose(rot), matmul(a, rot))
                    a(p, q) = 0.0_dp
                    a(q, p) = 0.0_dp
                    vectors = matmul(vectors, rot)
                end do
            end do
        end do
        do i = 1, 3
            values(i) = a(i, i)
        end do
        do i = 1, 2                       ! increasing order
            k = i - 1 + minloc(values(i:3), dim=1)
            if (k /= i) then
                tau = values(i)
                values(i) = values(k)
                values(k) = tau
                tmp = vectors(:, i)
                vectors(:, i) = vectors(:, k)
                vectors(:, k) = tmp
            end if
        end do
    end subroutine symmetric_eigen

end module field_transforms
