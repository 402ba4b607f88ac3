!> CALC_ERREUR (Code_Aster U4.81.04, code_aster/Cata/Commands/calc_erreur.py): the
!> Zhu-Zienkiewicz error estimators of plane elasticity (Code_Aster R4.10.01), on the plane
!> elements (D_PLAN, C_PLAN) of the result's model (doc/fields.md "CALC_ERREUR"):
!>  SIZ1_NOEU  the 1987 smoothing: sigma* = N sigma*_a, interpolated by the displacement's
!>             shape functions, the least-squares fit of sigma_h over the whole mesh:
!>             M sigma*_a = integral N^T sigma_h, M = integral N^T N (one system per
!>             component, the RIGI points of each cell; solved by conjugate gradients to
!>             round-off);
!>  SIZ2_NOEU  the 1992 smoothing (superconvergent patch recovery): around each vertex, a
!>             polynomial of the displacement's degree (TRIA3 1 x y, QUAD4 1 x y xy, TRIA6
!>             complete quadratic, QUAD8 serendipity, QUAD9 biquadratic) fitted in least
!>             squares to sigma_h at the RIGI points of the cells around it, evaluated at
!>             their nodes; a node takes the mean of the patches of the interior vertices
!>             it belongs to (a node in none, that of the vertices of its cells);
!>  ERZ1_ELEM, ERZ2_ELEM  per element, with e = sigma* - sigma_h and the compliance D^-1
!>             (R4.10.01 eq 2.2-1): ERREST = (integral e D^-1 e)^1/2, SIGCAL =
!>             (integral sigma_h D^-1 sigma_h)^1/2, NUEST = 100 ERREST / (ERREST^2 +
!>             SIGCAL^2)^1/2 (%); the same sums over the elements go to the .mess.
!> ERME_*, QI*, SING_*, ERTH_* are refused as not built.
module calc_erreur_command
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, clear_status, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cell_label, MAX_CELL_NODES, CELL_TRIA3, CELL_QUAD4, &
        CELL_TRIA6, CELL_QUAD8, CELL_QUAD9, CELL_TYPE_NODES, CELL_TYPE_CORNERS
    use model_types, only: is_plane_solid
    use model_material, only: material_of_cell
    use element_gauss_families, only: gauss_rule_t, MAX_GAUSS_POINTS
    use element_plane, only: plane_rigi_rule, plane_derivatives
    use field_types, only: field_t, field_init_nodes, field_init_cells, field_define_cells, &
        component_set_t, field_position, field_component, FIELD_ELEM
    use result_fields, only: result_put_field
    use analysis_result, only: result_concept_t
    use result_access, only: result_field_at
    use result_instants, only: selected_instants
    implicit none
    private

    !> Options built, and the stress components smoothed (SIEF_R of plane elements).
    character(len=*), parameter :: BUILT = 'SIZ1_NOEU ERZ1_ELEM SIZ2_NOEU ERZ2_ELEM'
    character(len=4), parameter :: CMPS(4) = ['SIXX', 'SIYY', 'SIZZ', 'SIXY']
    !> Conjugate gradients: relative residual reached, iterations allowed (times n).
    real(dp), parameter :: CG_TOLERANCE = 1.0e-15_dp
    integer, parameter :: CG_ITERATIONS_PER_UNKNOWN = 2

    !> The plane cells and, at their RIGI points, the weights times the Jacobian, the
    !> shape functions, the positions and sigma_h.
    type :: sampling_t
        integer(i4), allocatable :: cells(:)
        integer(i4), allocatable :: n_points(:)               !< per entry of cells
        real(dp), allocatable :: wdet(:, :)                   !< (MAX_GAUSS_POINTS, n)
        real(dp), allocatable :: shape(:, :, :)               !< (MAX_CELL_NODES, MAX_GP, n)
        real(dp), allocatable :: xy(:, :, :)                  !< (2, MAX_GP, n)
        real(dp), allocatable :: sigma(:, :, :)               !< (4, MAX_GP, n)
        real(dp), allocatable :: young(:), nu(:)
    end type sampling_t

    public :: run_calc_erreur

contains

    !> Handler of CALC_ERREUR (registered with reuse).
    !>  st : located errors: an option not built, a result without plane elements or
    !>       without SIEF_ELGA, a cell without ELAS
    subroutine run_calc_erreur(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(result_concept_t), allocatable, target :: copy
        type(result_concept_t), pointer :: res
        type(string_t), allocatable :: options(:)
        integer, allocatable :: indices(:)
        logical :: by_inst
        integer(i4) :: k, i
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        type is (result_concept_t)
            if (associated(cmd%reuse)) then
                res => p
            else
                allocate (copy, source=p)
                res => copy
            end if
        class default
            call cmd%error_at('RESULTAT', 'expected a result of an analysis, got ' // &
                p%type_name(), st)
            return
        end select
        call cmd%get_texts('OPTION', options, st)
        if (st%failed()) return
        do k = 1, size(options)
            if (index(' ' // BUILT // ' ', ' ' // options(k)%s // ' ') == 0) then
                call cmd%error_at('OPTION', 'OPTION ' // options(k)%s // ' is not built in ' // &
                    'parasol (' // BUILT // ' are)', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
        end do
        if (.not. res%has_structure) then
            call cmd%error_at('RESULTAT', 'the result knows no model: CALC_ERREUR computes ' // &
                'on the plane elements of an analysis''s model', st, STATUS_MODEL_ERROR)
            return
        end if
        call selected_instants(cmd, res, indices, by_inst, st)
        if (st%failed()) return
        do i = 1, size(indices)
            call estimate_at(ctx, res, int(indices(i), i4), options, st)
            if (st%failed()) then
                call relocate(cmd, st)
                return
            end if
        end do
        if (allocated(copy)) call move_alloc(copy, result)
    end subroutine run_calc_erreur

    ! The options at stored instant `at`.
    subroutine estimate_at(ctx, res, at, options, st)
        type(run_context_t), intent(inout) :: ctx
        type(result_concept_t), target, intent(inout) :: res
        integer(i4), intent(in) :: at
        type(string_t), intent(in) :: options(:)
        type(status_t), intent(out) :: st
        type(sampling_t) :: s
        real(dp), allocatable :: smooth(:, :)
        logical, allocatable :: has(:)
        type(field_t) :: f
        integer :: version, k
        character(len=9) :: noeu, elem
        call sample(res, at, s, st)
        if (st%failed()) return
        do version = 1, 2
            noeu = 'SIZ' // achar(48 + version) // '_NOEU'
            elem = 'ERZ' // achar(48 + version) // '_ELEM'
            if (.not. any([(options(k)%s == noeu .or. options(k)%s == elem, &
                k = 1, size(options))])) cycle
            if (version == 1) then
                call smooth_global(res%mesh, s, smooth, has, st)
            else
                call smooth_patches(res%mesh, s, smooth, has, st)
            end if
            if (st%failed()) return
            if (any([(options(k)%s == noeu, k = 1, size(options))])) then
                call nodal_field(res%mesh, smooth, has, f, st)
                if (st%failed()) return
                call result_put_field(res, at, noeu, f)
            end if
            if (any([(options(k)%s == elem, k = 1, size(options))])) then
                call error_field(ctx, res%mesh, s, smooth, elem, f, st)
                if (st%failed()) return
                call result_put_field(res, at, elem, f)
            end if
        end do
    end subroutine estimate_at

    ! The plane cells of the model and, at their RIGI points, what the estimators need.
    subroutine sample(res, at, s, st)
        type(result_concept_t), target, intent(inout) :: res
        integer(i4), intent(in) :: at
        type(sampling_t), intent(out) :: s
        type(status_t), intent(out) :: st
        type(field_t), pointer :: sief
        type(gauss_rule_t) :: rule
        real(dp) :: xy(2, MAX_CELL_NODES), n(MAX_CELL_NODES), dxy(2, MAX_CELL_NODES), det
        integer(i4) :: k, c, g, nn, m, i, j(4)
        integer(i8) :: pos
        integer(i4), allocatable :: cells(:)
        cells = pack([(c, c = 1, res%mesh%n_cells)], [(is_plane_solid(res%model%element(c)), &
            c = 1, res%mesh%n_cells)])
        if (size(cells) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the model has no plane element (D_PLAN, ' // &
                'C_PLAN): the Zhu-Zienkiewicz estimators are of plane elasticity')
            return
        end if
        call result_field_at(res, at, 'SIEF_ELGA', sief, st)
        if (st%failed()) return
        do k = 1, 4
            j(k) = field_component(sief, CMPS(k))
        end do
        if (any(j == 0)) then
            call set_error(st, STATUS_MODEL_ERROR, 'SIEF_ELGA lacks SIXX SIYY SIZZ SIXY')
            return
        end if
        s%cells = cells
        allocate (s%n_points(size(cells)), s%young(size(cells)), s%nu(size(cells)))
        allocate (s%wdet(MAX_GAUSS_POINTS, size(cells)), source=0.0_dp)
        allocate (s%shape(MAX_CELL_NODES, MAX_GAUSS_POINTS, size(cells)), source=0.0_dp)
        allocate (s%xy(2, MAX_GAUSS_POINTS, size(cells)), source=0.0_dp)
        allocate (s%sigma(4, MAX_GAUSS_POINTS, size(cells)), source=0.0_dp)
        do k = 1, size(cells, kind=i4)
            c = cells(k)
            nn = CELL_TYPE_NODES(res%mesh%cell_type(c))
            xy(:, 1:nn) = res%mesh%coords(1:2, res%mesh%cell_nodes(res%mesh%cell_ptr(c): &
                res%mesh%cell_ptr(c) + nn - 1))
            m = material_of_cell(res%materials, c)
            if (m == 0) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(res%mesh, c) // ' has no ' // &
                    'material (ELAS): the error is measured in its energy')
                return
            end if
            if (.not. res%materials%materials(m)%has_elas) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(res%mesh, c) // ': its ' // &
                    'material has no ELAS (E, NU)')
                return
            end if
            s%young(k) = res%materials%materials(m)%elas%e
            s%nu(k) = res%materials%materials(m)%elas%nu
            call plane_rigi_rule(res%mesh%cell_type(c), rule, st)
            if (st%failed()) return
            if (sief%n_points(c) /= rule%n) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(res%mesh, c) // ': ' // &
                    'SIEF_ELGA has ' // to_text(sief%n_points(c)) // ' points, its RIGI ' // &
                    'family ' // to_text(rule%n))
                return
            end if
            s%n_points(k) = rule%n
            do g = 1, rule%n
                call plane_derivatives(res%mesh%cell_type(c), xy(:, 1:nn), rule%xi(1, g), &
                    rule%xi(2, g), n(1:nn), dxy(:, 1:nn), det)
                s%wdet(g, k) = rule%w(g) * abs(det)
                s%shape(1:nn, g, k) = n(1:nn)
                s%xy(:, g, k) = matmul(xy(:, 1:nn), n(1:nn))
                do i = 1, 4
                    pos = field_position(sief, c, g, 1_i4, j(i))
                    if (pos > 0) s%sigma(i, g, k) = sief%values(pos)
                end do
            end do
        end do
    end subroutine sample

    ! ZZ1: the global least-squares fit (module header), by conjugate gradients with the
    ! diagonal as preconditioner on M = sum of the cells' N^T N (applied cell by cell).
    subroutine smooth_global(mesh, s, smooth, has, st)
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        real(dp), allocatable, intent(out) :: smooth(:, :)
        logical, allocatable, intent(out) :: has(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: b(:, :), diag(:), r(:, :), z(:, :), p(:, :), q(:, :)
        real(dp) :: rz(4), rz_new(4), alpha(4), norm_b(4)
        integer(i4) :: k, g, a, i, nn, it
        allocate (smooth(4, mesh%n_nodes), b(4, mesh%n_nodes), source=0.0_dp)
        allocate (diag(mesh%n_nodes), source=0.0_dp)
        allocate (has(mesh%n_nodes), source=.false.)
        do k = 1, size(s%cells, kind=i4)
            nn = CELL_TYPE_NODES(mesh%cell_type(s%cells(k)))
            do g = 1, s%n_points(k)
                do a = 1, nn
                    i = mesh%cell_nodes(mesh%cell_ptr(s%cells(k)) + a - 1)
                    has(i) = .true.
                    b(:, i) = b(:, i) + s%wdet(g, k) * s%shape(a, g, k) * s%sigma(:, g, k)
                    diag(i) = diag(i) + s%wdet(g, k) * s%shape(a, g, k)**2
                end do
            end do
        end do
        where (.not. has) diag = 1.0_dp
        if (any(has .and. .not. diag > 0.0_dp)) then
            call set_error(st, STATUS_MODEL_ERROR, 'a node of the plane cells has no mass ' // &
                '(a degenerate cell)')
            return
        end if
        allocate (r, source=b)
        allocate (z(4, mesh%n_nodes), p(4, mesh%n_nodes), q(4, mesh%n_nodes))
        norm_b = sqrt(sum(b**2, dim=2))
        z = r / spread(diag, 1, 4)
        p = z
        rz = sum(r * z, dim=2)
        do it = 1, CG_ITERATIONS_PER_UNKNOWN * count(has) + 10
            if (all(sqrt(sum(r**2, dim=2)) <= CG_TOLERANCE * norm_b)) exit
            call apply_mass(mesh, s, p, q)
            do k = 1, 4
                alpha(k) = 0.0_dp
                if (dot_product(p(k, :), q(k, :)) > 0.0_dp) &
                    alpha(k) = rz(k) / dot_product(p(k, :), q(k, :))
                smooth(k, :) = smooth(k, :) + alpha(k) * p(k, :)
                r(k, :) = r(k, :) - alpha(k) * q(k, :)
                z(k, :) = r(k, :) / diag
                rz_new(k) = dot_product(r(k, :), z(k, :))
                if (rz(k) > 0.0_dp) then
                    p(k, :) = z(k, :) + (rz_new(k) / rz(k)) * p(k, :)
                else
                    p(k, :) = z(k, :)
                end if
            end do
            rz = rz_new
        end do
        where (.not. spread(has, 1, 4)) smooth = 0.0_dp
    end subroutine smooth_global

    ! q = M p, cell by cell.
    subroutine apply_mass(mesh, s, p, q)
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        real(dp), intent(in) :: p(:, :)
        real(dp), intent(out) :: q(:, :)
        real(dp) :: at_point(4)
        integer(i4) :: k, g, a, nn, first
        q = 0.0_dp
        do k = 1, size(s%cells, kind=i4)
            nn = CELL_TYPE_NODES(mesh%cell_type(s%cells(k)))
            first = mesh%cell_ptr(s%cells(k))
            do g = 1, s%n_points(k)
                at_point = 0.0_dp
                do a = 1, nn
                    at_point = at_point + s%shape(a, g, k) * p(:, mesh%cell_nodes(first + a - 1))
                end do
                do a = 1, nn
                    q(:, mesh%cell_nodes(first + a - 1)) = q(:, mesh%cell_nodes(first + a - 1)) &
                        + s%wdet(g, k) * s%shape(a, g, k) * at_point
                end do
            end do
        end do
    end subroutine apply_mass

    ! ZZ2: superconvergent patch recovery (module header).
    subroutine smooth_patches(mesh, s, smooth, has, st)
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        real(dp), allocatable, intent(out) :: smooth(:, :)
        logical, allocatable, intent(out) :: has(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: ptr(:), items(:), hits(:), cells_of(:)
        logical, allocatable :: vertex(:), boundary(:), in_patch(:)
        real(dp), allocatable :: sum_interior(:, :), sum_any(:, :)
        integer(i4), allocatable :: n_interior(:), n_any(:)
        real(dp) :: centre(2), scale, values(4)
        integer(i4) :: k, a, v, c, nn, nc, ctype, j
        allocate (smooth(4, mesh%n_nodes), source=0.0_dp)
        allocate (has(mesh%n_nodes), vertex(mesh%n_nodes), source=.false.)
        call node_to_cells(mesh, s, ptr, items)
        call boundary_nodes(mesh, s, boundary)
        ctype = mesh%cell_type(s%cells(1))
        if (any(mesh%cell_type(s%cells) /= ctype)) then
            call set_error(st, STATUS_MODEL_ERROR, 'ZZ2 needs one cell type on the whole ' // &
                'mesh (Code_Aster R4.10.01, 4.2)')
            return
        end if
        do k = 1, size(s%cells, kind=i4)
            nc = CELL_TYPE_CORNERS(ctype)
            vertex(mesh%cell_nodes(mesh%cell_ptr(s%cells(k)):mesh%cell_ptr(s%cells(k)) + &
                nc - 1)) = .true.
        end do
        allocate (sum_interior(4, mesh%n_nodes), sum_any(4, mesh%n_nodes), source=0.0_dp)
        allocate (n_interior(mesh%n_nodes), n_any(mesh%n_nodes), source=0_i4)
        allocate (in_patch(mesh%n_nodes), source=.false.)
        nn = CELL_TYPE_NODES(ctype)
        do v = 1, mesh%n_nodes
            if (.not. vertex(v)) cycle
            cells_of = items(ptr(v):ptr(v + 1) - 1)
            centre = mesh%coords(1:2, v)
            scale = 0.0_dp
            do j = 1, size(cells_of, kind=i4)
                c = s%cells(cells_of(j))
                do a = 1, nn
                    scale = max(scale, norm2(mesh%coords(1:2, mesh%cell_nodes( &
                        mesh%cell_ptr(c) + a - 1)) - centre))
                end do
            end do
            if (.not. scale > 0.0_dp) cycle
            hits = [integer(i4) ::]
            do j = 1, size(cells_of, kind=i4)
                c = s%cells(cells_of(j))
                do a = 1, nn
                    if (.not. in_patch(mesh%cell_nodes(mesh%cell_ptr(c) + a - 1))) then
                        in_patch(mesh%cell_nodes(mesh%cell_ptr(c) + a - 1)) = .true.
                        hits = [hits, mesh%cell_nodes(mesh%cell_ptr(c) + a - 1)]
                    end if
                end do
            end do
            do j = 1, size(hits, kind=i4)
                in_patch(hits(j)) = .false.
                call patch_value(s, ctype, cells_of, centre, scale, &
                    mesh%coords(1:2, hits(j)), values, st)
                if (st%failed()) then
                    if (boundary(v)) then                 ! too few points: not used
                        call clear_status(st)
                        exit
                    end if
                    return
                end if
                sum_any(:, hits(j)) = sum_any(:, hits(j)) + values
                n_any(hits(j)) = n_any(hits(j)) + 1
                if (.not. boundary(v)) then
                    sum_interior(:, hits(j)) = sum_interior(:, hits(j)) + values
                    n_interior(hits(j)) = n_interior(hits(j)) + 1
                end if
            end do
        end do
        do a = 1, mesh%n_nodes
            if (n_interior(a) > 0) then
                smooth(:, a) = sum_interior(:, a) / real(n_interior(a), dp)
                has(a) = .true.
            else if (n_any(a) > 0) then
                smooth(:, a) = sum_any(:, a) / real(n_any(a), dp)
                has(a) = .true.
            end if
        end do
    end subroutine smooth_patches

    ! The patch polynomial fitted to sigma_h at the RIGI points of `cells_of` (indices into
    ! s%cells), evaluated at x; coordinates relative to the centre, scaled.
    subroutine patch_value(s, ctype, cells_of, centre, scale, x, values, st)
        type(sampling_t), intent(in) :: s
        integer(i4), intent(in) :: ctype, cells_of(:)
        real(dp), intent(in) :: centre(2), scale, x(2)
        real(dp), intent(out) :: values(4)
        type(status_t), intent(out) :: st
        real(dp) :: a(9, 9), b(9, 4), pv(9), det
        integer(i4) :: j, g, k, np, info
        integer(i4) :: ipiv(9)
        np = polynomial_size(ctype)
        a = 0.0_dp
        b = 0.0_dp
        do j = 1, size(cells_of)
            k = cells_of(j)
            do g = 1, s%n_points(k)
                call polynomial(ctype, (s%xy(:, g, k) - centre) / scale, pv)
                do info = 1, np
                    a(info, 1:np) = a(info, 1:np) + pv(info) * pv(1:np)
                    b(info, :) = b(info, :) + pv(info) * s%sigma(:, g, k)
                end do
            end do
        end do
        call solve_small(a(1:np, 1:np), b(1:np, :), np, det, ipiv)
        if (.not. abs(det) > 1.0e-12_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'a patch of ' // &
                to_text(size(cells_of)) // ' cell(s) has too few points for its polynomial')
            return
        end if
        call polynomial(ctype, (x - centre) / scale, pv)
        values = matmul(pv(1:np), b(1:np, :))
    end subroutine patch_value

    pure integer(i4) function polynomial_size(ctype) result(n)
        integer(i4), intent(in) :: ctype
        select case (ctype)
        case (CELL_TRIA3)
            n = 3
        case (CELL_QUAD4)
            n = 4
        case (CELL_TRIA6)
            n = 6
        case (CELL_QUAD8)
            n = 8
        case default
            n = 9
        end select
    end function polynomial_size

    ! The monomials of the displacement's degree on `ctype` at (x, y).
    pure subroutine polynomial(ctype, xy, pv)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(2)
        real(dp), intent(out) :: pv(9)
        real(dp) :: x, y
        x = xy(1)
        y = xy(2)
        pv = [1.0_dp, x, y, x * y, x * x, y * y, x * x * y, x * y * y, x * x * y * y]
        if (ctype == CELL_TRIA6) pv(1:6) = [1.0_dp, x, y, x * x, x * y, y * y]
    end subroutine polynomial

    ! Gaussian elimination with partial pivoting of a small system (in place: b becomes
    ! the solution); det the product of the pivots relative to the largest diagonal.
    pure subroutine solve_small(a, b, n, det, ipiv)
        real(dp), intent(inout) :: a(:, :), b(:, :)
        integer(i4), intent(in) :: n
        real(dp), intent(out) :: det
        integer(i4), intent(out) :: ipiv(:)
        real(dp) :: big, f, row(size(a, 2)), rowb(size(b, 2))
        integer(i4) :: i, k, p
        big = maxval(abs([(a(i, i), i = 1, n)]))
        det = 1.0_dp
        if (.not. big > 0.0_dp) then
            det = 0.0_dp
            return
        end if
        do k = 1, n
            p = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
            ipiv(k) = p
            if (p /= k) then
                row = a(k, :)
                a(k, :) = a(p, :)
                a(p, :) = row
                rowb = b(k, :)
                b(k, :) = b(p, :)
                b(p, :) = rowb
            end if
            if (.not. abs(a(k, k)) > 1.0e-13_dp * big) then
                det = 0.0_dp
                return
            end if
            do i = k + 1, n
                f = a(i, k) / a(k, k)
                a(i, k:n) = a(i, k:n) - f * a(k, k:n)
                b(i, :) = b(i, :) - f * b(k, :)
            end do
        end do
        do k = n, 1, -1
            b(k, :) = (b(k, :) - matmul(a(k, k + 1:n), b(k + 1:n, :))) / a(k, k)
        end do
    end subroutine solve_small

    ! For each node, the entries of s%cells around it (CSR).
    subroutine node_to_cells(mesh, s, ptr, items)
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        integer(i4), allocatable, intent(out) :: ptr(:), items(:)
        integer(i4), allocatable :: fill(:)
        integer(i4) :: k, a, i
        allocate (ptr(mesh%n_nodes + 1), source=0_i4)
        do k = 1, size(s%cells, kind=i4)
            do a = mesh%cell_ptr(s%cells(k)), mesh%cell_ptr(s%cells(k) + 1) - 1
                ptr(mesh%cell_nodes(a) + 1) = ptr(mesh%cell_nodes(a) + 1) + 1
            end do
        end do
        ptr(1) = 1
        do i = 1, mesh%n_nodes
            ptr(i + 1) = ptr(i + 1) + ptr(i)
        end do
        allocate (items(ptr(mesh%n_nodes + 1) - 1))
        allocate (fill(mesh%n_nodes), source=0_i4)
        do k = 1, size(s%cells, kind=i4)
            do a = mesh%cell_ptr(s%cells(k)), mesh%cell_ptr(s%cells(k) + 1) - 1
                i = mesh%cell_nodes(a)
                items(ptr(i) + fill(i)) = k
                fill(i) = fill(i) + 1
            end do
        end do
    end subroutine node_to_cells

    ! Nodes on the boundary of the plane cells: those of an edge that only one cell has.
    subroutine boundary_nodes(mesh, s, boundary)
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        logical, allocatable, intent(out) :: boundary(:)
        integer(i4), allocatable :: ptr(:), items(:)
        integer(i4) :: k, e, nc, a, b, j, shared, c
        allocate (boundary(mesh%n_nodes), source=.false.)
        call node_to_cells(mesh, s, ptr, items)
        do k = 1, size(s%cells, kind=i4)
            c = s%cells(k)
            nc = CELL_TYPE_CORNERS(mesh%cell_type(c))
            do e = 1, nc
                a = mesh%cell_nodes(mesh%cell_ptr(c) + e - 1)
                b = mesh%cell_nodes(mesh%cell_ptr(c) + mod(e, nc))
                shared = 0
                do j = ptr(a), ptr(a + 1) - 1
                    if (any(mesh%cell_nodes(mesh%cell_ptr(s%cells(items(j))): &
                        mesh%cell_ptr(s%cells(items(j)) + 1) - 1) == b)) shared = shared + 1
                end do
                if (shared < 2) then
                    boundary(a) = .true.
                    boundary(b) = .true.
                end if
            end do
        end do
    end subroutine boundary_nodes

    ! SIZ*_NOEU: SIEF_R SIXX SIYY SIZZ SIXY at the nodes of the plane cells.
    subroutine nodal_field(mesh, smooth, has, f, st)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: smooth(:, :)
        logical, intent(in) :: has(:)
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t) :: names(4)
        integer(i4) :: k
        do k = 1, 4
            names(k)%s = CMPS(k)
        end do
        call field_init_nodes(f, 'SIEF_R', names, mesh%n_nodes, st)
        if (st%failed()) return
        f%node_values = smooth
        f%node_has = spread(has, 1, 4)
    end subroutine nodal_field

    ! ERZ*_ELEM (module header) and the sums over the elements in the .mess.
    subroutine error_field(ctx, mesh, s, smooth, name, f, st)
        type(run_context_t), intent(inout) :: ctx
        type(mesh_t), intent(in) :: mesh
        type(sampling_t), intent(in) :: s
        real(dp), intent(in) :: smooth(:, :)
        character(len=*), intent(in) :: name
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t) :: names(3)
        type(component_set_t) :: sets(1)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        real(dp) :: e(4), sig(4), err2, norm2_, total_err, total_norm
        integer(i4) :: k, g, a, nn, first, c
        integer(i8) :: pos
        names(1)%s = 'ERREST'
        names(2)%s = 'NUEST'
        names(3)%s = 'SIGCAL'
        call field_init_cells(f, FIELD_ELEM, 'ERRE_R', names, mesh%n_cells, st)
        if (st%failed()) return
        allocate (n_points(mesh%n_cells), source=0_i4)
        allocate (n_sub(mesh%n_cells), cell_set(mesh%n_cells), source=1_i4)
        n_points(s%cells) = 1
        sets(1)%cmp = [1_i4, 2_i4, 3_i4]
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        total_err = 0.0_dp
        total_norm = 0.0_dp
        do k = 1, size(s%cells, kind=i4)
            c = s%cells(k)
            nn = CELL_TYPE_NODES(mesh%cell_type(c))
            first = mesh%cell_ptr(c)
            err2 = 0.0_dp
            norm2_ = 0.0_dp
            do g = 1, s%n_points(k)
                sig = s%sigma(:, g, k)
                e = -sig
                do a = 1, nn
                    e = e + s%shape(a, g, k) * smooth(:, mesh%cell_nodes(first + a - 1))
                end do
                err2 = err2 + s%wdet(g, k) * energy(e, s%young(k), s%nu(k))
                norm2_ = norm2_ + s%wdet(g, k) * energy(sig, s%young(k), s%nu(k))
            end do
            total_err = total_err + err2
            total_norm = total_norm + norm2_
            pos = field_position(f, c, 1_i4, 1_i4, 1_i4)
            f%values(pos) = sqrt(max(err2, 0.0_dp))
            f%values(pos + 2) = sqrt(max(norm2_, 0.0_dp))
            f%values(pos + 1) = relative(err2, norm2_)
        end do
        call ctx%write_mess('    CALC_ERREUR ' // name // ': error ' // &
            real_e13(sqrt(max(total_err, 0.0_dp))) // ', norm of sigma_h ' // &
            real_e13(sqrt(max(total_norm, 0.0_dp))) // ', relative ' // &
            real_e13(relative(total_err, total_norm)) // ' %')
    end subroutine error_field

    ! 100 err / (err^2 + norm^2)^1/2 from the squares (0 when both vanish).
    pure real(dp) function relative(err2, norm2_) result(pct)
        real(dp), intent(in) :: err2, norm2_
        pct = 0.0_dp
        if (err2 + norm2_ > 0.0_dp) pct = 100.0_dp * sqrt(max(err2, 0.0_dp) / (err2 + norm2_))
    end function relative

    ! sigma . D^-1 sigma of the components SIXX SIYY SIZZ SIXY (isotropic compliance; the
    ! plane stress elements have SIZZ = 0).
    pure real(dp) function energy(sig, young, nu) result(w)
        real(dp), intent(in) :: sig(4), young, nu
        w = (sig(1)**2 + sig(2)**2 + sig(3)**2 - 2.0_dp * nu * (sig(1) * sig(2) + &
            sig(2) * sig(3) + sig(1) * sig(3)) + 2.0_dp * (1.0_dp + nu) * sig(4)**2) / young
    end function energy

    ! A failed status located at OPTION (STATUS_MODEL_ERROR unless not built).
    subroutine relocate(cmd, st)
        type(command_t), intent(in) :: cmd
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message
        integer :: code
        message = st%message
        code = st%code
        if (code /= STATUS_NOT_IMPLEMENTED) code = STATUS_MODEL_ERROR
        call clear_status(st)
        call cmd%error_at('OPTION', message, st, code)
    end subroutine relocate

end module calc_erreur_command
