!> CALC_CHAMP's ENERGIE options computed from a result's displacements (Code_Aster's
!> option catalogue enel_elga/enel_elem/etot_elga/etot_elem, quantity ENER_R; doc/fields.md
!> "Energies"), on the cells whose element Code_Aster defines them for:
!>  ENEL_ELGA  the elastic energy density at the RIGI points (per unit volume of a plane
!>             element, per unit area of a plate):
!>             plane elements (D_PLAN, C_PLAN, every cell type): TOTALE = 1/2 sig : (eps -
!>             eps_th), the stress and strain of element_plane at the point (C_PLAN's EPZZ
!>             from sig_zz = 0, D_PLAN's restrained expansion counted through SIZZ); with
!>             eps_th = 0 it is 1/2 sig : C^-1 sig;
!>             DKT/DKQ plates, with N = Dm e + Dmf k, M = Dmf e + Df k, T (the DKT's shear
!>             from the moments' derivatives) and g = Dc^-1 T / 2 (DEGE's GAX GAY, half the
!>             engineering distortion, as Code_Aster's dktedg/dkqedg):
!>               MEMBRANE = 1/2 e . Dm e, FLEXION = 1/2 k . Df k, COUPL_MF = e . Dmf k,
!>               CISAILLE = 1/2 g . Dc g = 1/8 T . Dc^-1 T, TOTALE their sum
!>             (Code_Aster's te0412, linear case: it doubles DEGE's EXY and KXY back to
!>             engineering values but takes GAX GAY as they are, so its CISAILLE is a
!>             quarter of the shear strain energy 1/2 T . Dc^-1 T; parasol reports
!>             Code_Aster's quantity)
!>             (e, k engineering membrane strains and curvatures; the section's rigidities
!>             of model_plate_section: ELAS, ELAS_COQUE, laminates, EXCENTREMENT);
!>  ENEL_ELEM  its integral over the cell, sum_g w_g |J_g| (density at g), same components;
!>  ETOT_ELGA  plane elements only (Code_Aster defines it for no plate or spring): the
!>             total strain energy density accumulated over the result's stored instants by
!>             the trapezoidal rule, ETOT(t_i) = ETOT(t_i-1) + 1/2 (sig(t_i-1) + sig(t_i)) :
!>             (eps(t_i) - eps(t_i-1)), from a natural state (sig = eps = 0, ETOT = 0)
!>             before the first stored instant; an ETOT_ELGA the result stores at the instant
!>             before is taken as it is, else the sum is made from the first instant;
!>  ETOT_ELEM  the integral of ETOT_ELGA over the cell (TOTALE).
!> Springs (DIS_T, DIS_TR, DIS_CHOC ...) have none of these in Code_Aster's catalogue: they
!> are left out of the fields, as Code_Aster leaves out the elements without the option.
!> Not built (located errors): plate cells with thermal strains (their mechanical strains
!> are not split off here).
module energy_fields
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t
    use deck_catalog, only: split_words
    use mesh_types, only: cell_label, MAX_CELL_NODES
    use model_types, only: is_plate, is_plane_solid
    use field_types, only: field_t, component_set_t, field_init_cells, field_define_cells, &
        field_position, FIELD_ELGA, FIELD_ELEM
    use result_fields, only: result_field_index
    use analysis_result, only: result_concept_t
    use plate_options, only: plate_cell_t, plate_prepare
    use element_plate_fields, only: plate_point_strains, plate_point_shear
    use element_gauss_families, only: gauss_rule_t, gauss_family, FORMULATION_PLATE, &
        MAX_GAUSS_POINTS
    use element_plane, only: plane_law_t, plane_rigi_rule, plane_point_state, &
        plane_derivatives
    use assembly_plane_law, only: plane_cell_law
    use assembly_varc, only: plate_thermal_strains, plane_thermal_strains
    implicit none
    private

    !> The components of ENER_R the options give (Code_Aster's meca_dkt EENERPG; plane
    !> elements and ETOT: TOTALE alone, CENEISO/EENEISO).
    character(len=*), parameter, public :: ENERGY_CMPS = 'TOTALE MEMBRANE FLEXION ' // &
        'CISAILLE COUPL_MF'
    integer(i4), parameter :: N_PLATE_CMPS = 5
    integer(i4), parameter :: SET_PLATE = 1, SET_PLANE = 2

    public :: energy_field

contains

    !> ENEL_ELGA, ENEL_ELEM, ETOT_ELGA or ETOT_ELEM of result r at stored instant `at`, on the
    !> cells of `cells` that have it (module header).
    !>  st : an element failure naming the cell; STATUS_MODEL_ERROR when no cell asked for
    !>       has the option; STATUS_NOT_IMPLEMENTED for a plate with thermal strains
    subroutine energy_field(r, at, name, cells, f, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        logical, intent(in) :: cells(:)
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        type(component_set_t) :: sets(2)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        real(dp) :: dens(N_PLATE_CMPS, MAX_GAUSS_POINTS), wdet(MAX_GAUSS_POINTS)
        logical :: total, per_cell
        integer(i4) :: c, np, nc, g, j
        integer(i8) :: pos
        total = name(1:4) == 'ETOT'
        per_cell = name(6:9) == 'ELEM'
        if (.not. (r%has_state .and. r%has_structure)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the result holds no displacement to ' // &
                'compute from (a result of MECA_STATIQUE or STAT_NON_LINE has one)')
            return
        end if
        if (total) then
            call split_words('TOTALE', names)
        else
            call split_words(ENERGY_CMPS, names)
        end if
        call field_init_cells(f, merge(FIELD_ELEM, FIELD_ELGA, per_cell), 'ENER_R', names, &
            r%mesh%n_cells, st)
        if (st%failed()) return
        sets(SET_PLATE)%cmp = [(j, j = 1, size(names, kind=i4))]
        sets(SET_PLANE)%cmp = [1_i4]
        allocate (n_points(r%mesh%n_cells), n_sub(r%mesh%n_cells), &
            cell_set(r%mesh%n_cells), source=0_i4)
        n_sub = 1
        do c = 1, r%mesh%n_cells
            if (.not. cells(c)) cycle
            if (is_plane_solid(r%model%element(c))) then
                cell_set(c) = SET_PLANE
            else if (is_plate(r%model%element(c)) .and. .not. total) then
                cell_set(c) = SET_PLATE
            else
                cycle
            end if
            n_points(c) = 1
            if (.not. per_cell) call point_count(r, c, n_points(c), st)
            if (st%failed()) return
        end do
        if (all(cell_set == 0)) then
            if (total) then
                call set_error(st, STATUS_MODEL_ERROR, name // ' is defined on none of ' // &
                    'the cells asked for: Code_Aster defines it on plane elements (D_PLAN, ' // &
                    'C_PLAN) only')
            else
                call set_error(st, STATUS_MODEL_ERROR, name // ' is defined on none of ' // &
                    'the cells asked for: Code_Aster defines it on plane elements (D_PLAN, ' // &
                    'C_PLAN) and DKT/DKQ plates')
            end if
            return
        end if
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, r%mesh%n_cells
            if (cell_set(c) == 0) cycle
            if (total) then
                call total_densities(r, c, at, np, dens(1, :), wdet, st)
            else if (cell_set(c) == SET_PLANE) then
                call plane_densities(r, c, r%depl(:, at), r%inst(at), np, dens(1, :), wdet, st)
            else
                call plate_densities(r, c, r%depl(:, at), r%inst(at), np, dens, wdet, st)
            end if
            if (st%failed()) return
            nc = size(sets(cell_set(c))%cmp, kind=i4)
            do j = 1, nc
                if (per_cell) then
                    pos = field_position(f, c, 1_i4, 1_i4, j)
                    f%values(pos) = sum(wdet(1:np) * dens(j, 1:np))
                else
                    do g = 1, np
                        f%values(field_position(f, c, g, 1_i4, j)) = dens(j, g)
                    end do
                end if
            end do
        end do
    end subroutine energy_field

    ! The RIGI points of a plate or plane cell.
    subroutine point_count(r, c, n, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c
        integer(i4), intent(out) :: n
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        call cell_rule(r, c, rule, st)
        n = rule%n
    end subroutine point_count

    ! The RIGI rule of a plate or plane cell (Code_Aster's families, element_gauss_families).
    subroutine cell_rule(r, c, rule, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        if (is_plate(r%model%element(c))) then
            call gauss_family(FORMULATION_PLATE, r%mesh%cell_type(c), 'RIGI', rule, st)
        else
            call plane_rigi_rule(r%mesh%cell_type(c), rule, st)
        end if
        if (st%ok() .and. rule%n < 1) call set_error(st, STATUS_MODEL_ERROR, 'no Gauss points')
        if (st%failed()) st%message = cell_label(r%mesh, c) // ': ' // st%message
    end subroutine cell_rule

    ! A plane cell's stresses, strains and thermal strains at its RIGI points for the
    ! displacements u at instant t, and w_g |J_g|.
    subroutine plane_state(r, c, u, t, np, sig, eps, eps0, wdet, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: u(:), t
        integer(i4), intent(out) :: np
        real(dp), intent(out) :: sig(4, MAX_GAUSS_POINTS), eps(4, MAX_GAUSS_POINTS), &
            eps0(4, MAX_GAUSS_POINTS), wdet(MAX_GAUSS_POINTS)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        type(plane_law_t) :: law
        real(dp) :: xy(2, MAX_CELL_NODES), ue(2 * MAX_CELL_NODES), n(MAX_CELL_NODES)
        real(dp) :: dxy(2, MAX_CELL_NODES), det
        logical :: has
        integer(i4) :: nn, i, k, node, eq, ctype, g
        np = 0
        ctype = r%mesh%cell_type(c)
        nn = r%mesh%cell_ptr(c + 1) - r%mesh%cell_ptr(c)
        do i = 1, nn
            node = r%mesh%cell_nodes(r%mesh%cell_ptr(c) + i - 1)
            xy(:, i) = r%mesh%coords(1:2, node)
            do k = 1, 2
                eq = r%dofs%equation(k, node)
                ue(2 * i - 2 + k) = 0.0_dp
                if (eq > 0) ue(2 * i - 2 + k) = u(eq)
            end do
        end do
        call cell_rule(r, c, rule, st)
        if (st%failed()) return
        np = rule%n
        call plane_cell_law(r%mesh, r%model, r%materials, r%cara, c, law, st)
        if (st%ok()) call plane_thermal_strains(r%mesh, r%model, r%materials, c, t, rule, &
            eps0(:, 1:np), has, st)
        if (st%ok()) then
            if (.not. has) eps0(:, 1:np) = 0.0_dp
            call plane_point_state(ctype, xy(:, 1:nn), law, ue(1:2 * nn), rule, &
                sig(:, 1:np), eps(:, 1:np), st, eps0(:, 1:np))
        end if
        if (st%failed()) then
            st%message = cell_label(r%mesh, c) // ': ' // st%message
            return
        end if
        do g = 1, np
            call plane_derivatives(ctype, xy(:, 1:nn), rule%xi(1, g), rule%xi(2, g), n, dxy, &
                det)
            wdet(g) = rule%w(g) * abs(det)
        end do
    end subroutine plane_state

    ! sig : eps with Code_Aster's components (SIXX SIYY SIZZ SIXY; EPXY half the angle).
    pure real(dp) function contract(sig, eps)
        real(dp), intent(in) :: sig(4), eps(4)
        contract = sig(1) * eps(1) + sig(2) * eps(2) + sig(3) * eps(3) + 2.0_dp * sig(4) * eps(4)
    end function contract

    ! ENEL densities of a plane cell: 1/2 sig : (eps - eps_th) at each point.
    subroutine plane_densities(r, c, u, t, np, dens, wdet, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: u(:), t
        integer(i4), intent(out) :: np
        real(dp), intent(out) :: dens(:), wdet(:)
        type(status_t), intent(out) :: st
        real(dp) :: sig(4, MAX_GAUSS_POINTS), eps(4, MAX_GAUSS_POINTS), &
            eps0(4, MAX_GAUSS_POINTS), e0(4)
        integer(i4) :: g
        call plane_state(r, c, u, t, np, sig, eps, eps0, wdet, st)
        if (st%failed()) return
        do g = 1, np
            e0 = eps0(:, g)
            e0(4) = e0(4) / 2.0_dp          ! the thermal shear as a tensor component
            dens(g) = 0.5_dp * contract(sig(:, g), eps(:, g) - e0)
        end do
    end subroutine plane_densities

    ! ETOT densities of a plane cell at stored instant `at` (module header).
    subroutine total_densities(r, c, at, np, dens, wdet, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c, at
        integer(i4), intent(out) :: np
        real(dp), intent(out) :: dens(:), wdet(:)
        type(status_t), intent(out) :: st
        real(dp) :: sig0(4, MAX_GAUSS_POINTS), eps0(4, MAX_GAUSS_POINTS)
        real(dp) :: sig1(4, MAX_GAUSS_POINTS), eps1(4, MAX_GAUSS_POINTS), th(4, MAX_GAUSS_POINTS)
        integer(i4) :: first, j, g, k
        integer(i8) :: pos
        sig0 = 0.0_dp
        eps0 = 0.0_dp
        dens = 0.0_dp
        first = 1
        call point_count(r, c, np, st)
        if (st%failed()) return
        if (at > 1) then                     ! the instant before as the result stores it
            k = result_field_index(r, at - 1_i4, 'ETOT_ELGA')
            if (k > 0) then
                associate (prev => r%stored(at - 1)%items(k)%field)
                    if (prev%n_points(c) == np) then
                        do g = 1, np
                            pos = field_position(prev, c, g, 1_i4, 1_i4)
                            if (pos > 0) dens(g) = prev%values(pos)
                        end do
                        first = at
                        call plane_state(r, c, r%depl(:, at - 1), r%inst(at - 1), np, sig0, &
                            eps0, th, wdet, st)
                        if (st%failed()) return
                    end if
                end associate
            end if
        end if
        do j = first, at
            call plane_state(r, c, r%depl(:, j), r%inst(j), np, sig1, eps1, th, wdet, st)
            if (st%failed()) return
            do g = 1, np
                dens(g) = dens(g) + 0.5_dp * contract(sig0(:, g) + sig1(:, g), &
                    eps1(:, g) - eps0(:, g))
            end do
            sig0 = sig1
            eps0 = eps1
        end do
    end subroutine total_densities

    ! ENEL densities of a plate cell (module header) at its RIGI points.
    subroutine plate_densities(r, c, u, t, np, dens, wdet, st)
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: u(:), t
        integer(i4), intent(out) :: np
        real(dp), intent(out) :: dens(:, :), wdet(:)
        type(status_t), intent(out) :: st
        type(plate_cell_t) :: pc
        type(gauss_rule_t) :: rule
        real(dp) :: dm(3, 3), dmf(3, 3), df(3, 3), dc(2, 2), dci(2, 2), ddet, e(3), k(3), &
            tt(2), gam(2), det
        real(dp), allocatable :: eps_th(:, :)
        logical :: has
        integer(i4) :: g
        np = 0
        call cell_rule(r, c, rule, st)
        if (st%ok()) call plate_prepare(r%mesh, r%dofs, r%cara, r%materials, c, u, pc, st)
        if (st%failed()) return
        np = rule%n
        allocate (eps_th(3 * pc%layers, np))
        call plate_thermal_strains(r%mesh, r%materials, r%cara, c, t, rule%xi(:, 1:np), &
            eps_th, has, st)
        if (st%failed()) return
        if (has) then
            call set_error(st, STATUS_NOT_IMPLEMENTED, cell_label(r%mesh, c) // ' has ' // &
                'thermal strains (AFFE_VARC): the elastic energy of a plate with them is ' // &
                'not built by parasol')
            return
        end if
        dmf = 0.0_dp
        dci = 0.0_dp
        if (pc%homogeneous) then
            dm = pc%dm
            df = pc%df
            dc = reshape([pc%dc, 0.0_dp, 0.0_dp, pc%dc], [2, 2])
            if (pc%dc > 0.0_dp) dci = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2]) / pc%dc
        else
            dm = pc%section%dm
            dmf = pc%section%dmf
            df = pc%section%df
            dc = pc%section%dc
            ddet = dc(1, 1) * dc(2, 2) - dc(1, 2) * dc(2, 1)
            if (abs(ddet) > 0.0_dp) then
                dci(1, :) = [dc(2, 2), -dc(1, 2)] / ddet
                dci(2, :) = [-dc(2, 1), dc(1, 1)] / ddet
            end if
        end if
        do g = 1, np
            call plate_point_strains(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), &
                rule%xi(:, g), e, k, det)
            call plate_point_shear(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), df, &
                rule%xi(:, g), tt)
            dens(2, g) = 0.5_dp * dot_product(e, matmul(dm, e))
            dens(3, g) = 0.5_dp * dot_product(k, matmul(df, k))
            gam = 0.5_dp * matmul(dci, tt)      ! DEGE's GAX GAY (tensor shear strains)
            dens(4, g) = 0.5_dp * dot_product(gam, matmul(dc, gam))
            dens(5, g) = dot_product(e, matmul(dmf, k))
            dens(1, g) = sum(dens(2:5, g))
            wdet(g) = rule%w(g) * abs(det)
        end do
    end subroutine plate_densities

end module energy_fields
