!> Element fields computed from a result's displacements, cell by cell, for every element
!> family of the model (doc/fields.md):
!>  SIEF_ELGA  the state of stress of each element at its Gauss points: a plate's
!>             stresses SIXX SIYY SIZZ SIXY SIXZ SIYZ at its layer sub-points
!>             (plate_options PLATE_STRESS); a discrete spring's forces N VY VZ (N VY in
!>             2D) in its element frame, at its points (SEG2: its two nodes, POI1: its
!>             node): linear springs from K u (Code_Aster ef0042: node 1 gives -f1, node 2
!>             f2), DIS_CHOC springs from the state the analysis stored;
!>             a plane element's (D_PLAN, C_PLAN) SIXX SIYY SIZZ SIXY at its RIGI points
!>             (element_plane: D_PLAN's SIZZ from the restrained expansion, C_PLAN's 0);
!>  EPSI_ELGA  the strains at the same points: a plate's EPXX EPYY EPZZ EPXY EPXZ EPYZ at
!>             its layer sub-points, a plane element's EPXX EPYY EPZZ EPXY (C_PLAN's EPZZ
!>             from sig_zz = 0, D_PLAN's 0);
!>  EPME_ELGA  a plane element's mechanical strain: EPSI less the command-variable strains
!>             (thermal, HYDR, SECH; assembly_varc), Code_Aster's EPME;
!>  EPSP_ELGA  a plane element's inelastic strain: EPME less the elastic strain of the
!>             stress, S SIEF (S the compliance of its law), Code_Aster's EPSP; zero up to
!>             rounding for parasol's elastic laws;
!>  plate-only options at RIGI points or at the nodes (plate_options kinds).
!> Two passes: the layout of every cell (points, sub-points, components), then the values,
!> written in place (no per-cell allocation: the 128x512 plate has 65 536 cells).
module element_fields
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use deck_catalog, only: split_words
    use mesh_types, only: mesh_t, cell_label, CELL_POI1, CELL_SEG2, MAX_CELL_NODES
    use model_types, only: is_plate, is_discrete, is_discrete_2d, is_plane_solid
    use model_cara_elem, only: ORIENT_ANGL_VRIL, ORIENT_ANGL_NAUT
    use element_discrete, only: segment_rotation, segment_rotation_2d, nautical_rotation
    use element_spring_fields, only: SPRING_POINTS
    use assembly_system, only: structure_t, element_equations, cell_response, &
        MAX_ELEMENT_DOFS
    use field_types, only: field_t, component_set_t, field_init_cells, field_define_cells, &
        FIELD_ELGA, FIELD_ELNO
    use analysis_result, only: result_concept_t
    use plate_options, only: plate_cell_t, plate_prepare, plate_values, plate_value_count, &
        PLATE_STRESS, PLATE_STRAIN, PLATE_STRESS_CMPS, PLATE_STRAIN_CMPS, &
        PLATE_FORCES
    use element_gauss_families, only: gauss_rule_t, gauss_family, FORMULATION_PLATE, &
        MAX_GAUSS_POINTS
    use element_plane, only: plane_law_t, plane_rigi_rule, plane_point_state
    use assembly_plane_law, only: plane_cell_law
    use assembly_varc, only: plate_thermal_strains, plane_thermal_strains
    implicit none
    private

    public :: state_sief_elga, strain_field, plate_field, result_structure

    !> The strains strain_field gives (strain_kind): EPSI, EPME, EPSP (module header).
    integer(i4), parameter, public :: STRAIN_TOTAL = 0, STRAIN_MECHANICAL = 1, &
        STRAIN_INELASTIC = 2

contains

    !> The structure of a result as the assembly layer holds it (a copy).
    !>  st : STATUS_MODEL_ERROR for a result that does not know the structure it was
    !>       computed on (CREA_RESU: give MODELE, CHAM_MATER, CARA_ELEM)
    subroutine result_structure(res, s, st)
        type(result_concept_t), intent(in) :: res
        type(structure_t), intent(out) :: s
        type(status_t), intent(out) :: st
        if (.not. res%has_structure) then
            call set_error(st, STATUS_MODEL_ERROR, 'the result does not know the model it ' // &
                'was computed on (give MODELE, CHAM_MATER and CARA_ELEM)')
            return
        end if
        s%mesh = res%mesh
        s%model = res%model
        s%materials = res%materials
        s%cara = res%cara
        s%dofs = res%dofs
        s%choc = res%choc
    end subroutine result_structure

    !> SIEF_ELGA at stored instant `at` of an analysis result (module header), on the
    !> cells of `cells` (every cell when absent).
    !>  st : element failures naming the cell; plane elements not built yet
    subroutine state_sief_elga(res, at, f, st, cells)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: at
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: cells(:)
        type(structure_t) :: s
        type(string_t), allocatable :: cmps(:)
        type(component_set_t) :: sets(4)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:), spring_of(:)
        integer(i4) :: c, kind
        logical :: want, linear_springs
        if (.not. res%has_structure) then
            call set_error(st, STATUS_MODEL_ERROR, 'SIEF_ELGA: the result does not know ' // &
                'the model it was computed on')
            return
        end if
        call split_words(PLATE_STRESS_CMPS // ' N VY VZ', cmps)
        call field_init_cells(f, FIELD_ELGA, 'SIEF_R', cmps, res%mesh%n_cells, st)
        if (st%failed()) return
        sets(1)%cmp = [1_i4, 2_i4, 3_i4, 4_i4, 5_i4, 6_i4]     ! plates
        sets(2)%cmp = [7_i4, 8_i4, 9_i4]                       ! 3D springs
        sets(3)%cmp = [7_i4, 8_i4]                             ! 2D springs
        sets(4)%cmp = [1_i4, 2_i4, 3_i4, 4_i4]                 ! plane elements
        allocate (n_points(res%mesh%n_cells), n_sub(res%mesh%n_cells), &
            cell_set(res%mesh%n_cells), source=0_i4)
        allocate (spring_of(res%mesh%n_cells), source=0_i4)
        if (allocated(res%spring_cell)) then
            do c = 1, size(res%spring_cell)
                spring_of(res%spring_cell(c)) = c
            end do
        end if
        do c = 1, res%mesh%n_cells
            want = .true.
            if (present(cells)) want = cells(c)
            if (.not. want) cycle
            kind = res%model%element(c)
            if (is_plate(kind)) then
                n_points(c) = merge(4_i4, 3_i4, res%mesh%cell_ptr(c + 1) - &
                    res%mesh%cell_ptr(c) == 4)
                n_sub(c) = 3 * max(1_i4, res%cara%coque_layers(c))
                cell_set(c) = 1
            else if (is_discrete(kind)) then
                n_points(c) = merge(1_i4, SPRING_POINTS, res%mesh%cell_type(c) == CELL_POI1)
                n_sub(c) = 1
                cell_set(c) = merge(3_i4, 2_i4, is_discrete_2d(kind))
            else if (is_plane_solid(kind)) then
                n_points(c) = plane_point_count(res, c)
                n_sub(c) = 1
                cell_set(c) = 4
            end if
        end do
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        if (any(n_points == 0 .and. cell_set > 0)) then
            call plane_rule_error(res, n_points, cell_set, st)
            return
        end if
        ! the structure (a copy of the mesh and model) only for linear springs' K u: the
        ! analysis stored the DIS_CHOC springs' forces
        linear_springs = .false.
        do c = 1, res%mesh%n_cells
            if (cell_set(c) /= 2 .and. cell_set(c) /= 3) cycle
            if (spring_of(c) > 0) then
                if (res%choc(c)) cycle
            end if
            linear_springs = .true.
            exit
        end do
        if (linear_springs) then
            call result_structure(res, s, st)
            if (st%failed()) return
        end if
        do c = 1, res%mesh%n_cells
            if (n_points(c) == 0) cycle
            if (cell_set(c) == 1) then
                call plate_cell_values(res, c, res%depl(:, at), PLATE_STRESS, .false., &
                    f%values(f%offset(c) + 1:f%offset(c + 1)), st, inst=res%inst(at))
            else if (cell_set(c) == 4) then
                call plane_cell_values(res, c, res%depl(:, at), .true., &
                    f%values(f%offset(c) + 1:f%offset(c + 1)), st, inst=res%inst(at))
            else if (spring_of(c) > 0 .and. res%choc(c)) then
                call stored_spring_values(res, spring_of(c), at, n_points(c), &
                    size(sets(cell_set(c))%cmp, kind=i4), &
                    f%values(f%offset(c) + 1:f%offset(c + 1)))
            else
                call linear_spring_values(s, c, res%depl(:, at), n_points(c), &
                    size(sets(cell_set(c))%cmp, kind=i4), &
                    f%values(f%offset(c) + 1:f%offset(c + 1)), st)
            end if
            if (st%failed()) return
        end do
    end subroutine state_sief_elga

    !> EPSI_ELGA at the Gauss points of the plates and plane elements of `cells` (every
    !> cell when absent) for the displacements u (module header); with strain_kind
    !> STRAIN_MECHANICAL or STRAIN_INELASTIC, EPME_ELGA or EPSP_ELGA of the plane elements.
    !>  st : element failures naming the cell; EPME / EPSP asked on a plate cell
    subroutine strain_field(res, u, f, st, cells, inst, strain_kind)
        type(result_concept_t), intent(in) :: res
        real(dp), intent(in) :: u(:)
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: cells(:)
        real(dp), intent(in), optional :: inst     !< the instant (C_PLAN's thermal EPZZ)
        integer(i4), intent(in), optional :: strain_kind
        type(string_t), allocatable :: cmps(:)
        type(component_set_t) :: sets(2)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        integer(i4) :: c, kind, which
        logical :: want
        which = STRAIN_TOTAL
        if (present(strain_kind)) which = strain_kind
        call split_words(PLATE_STRAIN_CMPS, cmps)
        call field_init_cells(f, FIELD_ELGA, 'EPSI_R', cmps, res%mesh%n_cells, st)
        if (st%failed()) return
        sets(1)%cmp = [1_i4, 2_i4, 3_i4, 4_i4, 5_i4, 6_i4]     ! plates
        sets(2)%cmp = [1_i4, 2_i4, 3_i4, 4_i4]                 ! plane elements
        allocate (n_points(res%mesh%n_cells), n_sub(res%mesh%n_cells), &
            cell_set(res%mesh%n_cells), source=0_i4)
        do c = 1, res%mesh%n_cells
            want = .true.
            if (present(cells)) want = cells(c)
            if (.not. want) cycle
            kind = res%model%element(c)
            if (is_plate(kind) .and. which /= STRAIN_TOTAL) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(res%mesh, c) // ': ' // &
                    trim(merge('EPME_ELGA', 'EPSP_ELGA', which == STRAIN_MECHANICAL)) // &
                    ' is built for the plane elements (D_PLAN, C_PLAN), not for plates ' // &
                    '(restrict CALC_CHAMP with GROUP_MA)')
                return
            else if (is_plate(kind)) then
                n_points(c) = merge(4_i4, 3_i4, res%mesh%cell_ptr(c + 1) - &
                    res%mesh%cell_ptr(c) == 4)
                n_sub(c) = 3 * max(1_i4, res%cara%coque_layers(c))
                cell_set(c) = 1
            else if (is_plane_solid(kind)) then
                n_points(c) = plane_point_count(res, c)
                n_sub(c) = 1
                cell_set(c) = 2
            end if
        end do
        if (any(n_points == 0 .and. cell_set > 0)) then
            call plane_rule_error(res, n_points, cell_set, st)
            return
        end if
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, res%mesh%n_cells
            if (cell_set(c) == 1) then
                call plate_cell_values(res, c, u, PLATE_STRAIN, .false., &
                    f%values(f%offset(c) + 1:f%offset(c + 1)), st)
            else if (cell_set(c) == 2) then
                call plane_cell_values(res, c, u, .false., &
                    f%values(f%offset(c) + 1:f%offset(c + 1)), st, inst, which)
            end if
            if (st%failed()) return
        end do
    end subroutine strain_field

    !> The RIGI points of a plane cell (0 for a cell type without them).
    integer(i4) function plane_point_count(res, c) result(n)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: c
        type(gauss_rule_t) :: rule
        type(status_t) :: st
        call plane_rigi_rule(res%mesh%cell_type(c), rule, st)
        n = 0
        if (st%ok()) n = rule%n
    end function plane_point_count

    !> The error of the first plane cell whose type has no RIGI points.
    subroutine plane_rule_error(res, n_points, cell_set, st)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: n_points(:), cell_set(:)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        integer(i4) :: c
        do c = 1, size(n_points, kind=i4)
            if (n_points(c) > 0 .or. cell_set(c) == 0) cycle
            call plane_rigi_rule(res%mesh%cell_type(c), rule, st)
            if (st%ok()) call set_error(st, STATUS_MODEL_ERROR, 'no Gauss points')
            st%message = cell_label(res%mesh, c) // ': ' // st%message
            return
        end do
    end subroutine plane_rule_error

    !> A plane cell's stresses SIXX SIYY SIZZ SIXY (stresses) or strains EPXX EPYY EPZZ
    !> EPXY at its RIGI points, point by point (element_plane plane_point_state), from its
    !> material's ELAS and the displacements u (an equation vector of the result's dofs);
    !> with `inst`, the thermal strains of AFFE_VARC there (assembly_varc) are taken off
    !> the stresses and give C_PLAN's EPZZ; strain_kind (STRAIN_MECHANICAL, STRAIN_INELASTIC)
    !> makes the strains EPME or EPSP (module header).
    !>  st : STATUS_MODEL_ERROR naming the cell (no material, no ELAS, a degenerate cell)
    subroutine plane_cell_values(res, c, u, stresses, values, st, inst, strain_kind)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: stresses
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: inst
        integer(i4), intent(in), optional :: strain_kind
        real(dp) :: eps0(4, MAX_GAUSS_POINTS), elastic(4)
        logical :: has
        type(gauss_rule_t) :: rule
        type(plane_law_t) :: law
        real(dp) :: xy(2, MAX_CELL_NODES), ue(2 * MAX_CELL_NODES)
        real(dp) :: sig(4, MAX_GAUSS_POINTS), eps(4, MAX_GAUSS_POINTS)
        integer(i4) :: nn, i, k, node, eq, ctype, which, g
        which = STRAIN_TOTAL
        if (present(strain_kind)) which = strain_kind
        ctype = res%mesh%cell_type(c)
        nn = res%mesh%cell_ptr(c + 1) - res%mesh%cell_ptr(c)
        do i = 1, nn
            node = res%mesh%cell_nodes(res%mesh%cell_ptr(c) + i - 1)
            xy(:, i) = res%mesh%coords(1:2, node)
            do k = 1, 2
                eq = res%dofs%equation(k, node)
                ue(2 * i - 2 + k) = 0.0_dp
                if (eq > 0) ue(2 * i - 2 + k) = u(eq)
            end do
        end do
        call plane_cell_law(res%mesh, res%model, res%materials, res%cara, c, law, st)
        if (st%ok()) call plane_rigi_rule(ctype, rule, st)
        has = .false.
        eps0 = 0.0_dp
        if (st%ok() .and. present(inst)) call plane_thermal_strains(res%mesh, res%model, &
            res%materials, c, inst, rule, eps0(:, 1:rule%n), has, st)
        if (st%ok() .and. has) then
            call plane_point_state(ctype, xy(:, 1:nn), law, ue(1:2 * nn), rule, &
                sig(:, 1:rule%n), eps(:, 1:rule%n), st, eps0(:, 1:rule%n))
        else if (st%ok()) then
            call plane_point_state(ctype, xy(:, 1:nn), law, ue(1:2 * nn), rule, &
                sig(:, 1:rule%n), eps(:, 1:rule%n), st)
        end if
        if (st%failed()) then
            st%message = cell_label(res%mesh, c) // ': ' // st%message
            return
        end if
        ! EPME: less the command-variable strains; EPSP: less the elastic strain S sig too
        ! (tensor shear EPXY: half the engineering one)
        if (.not. stresses .and. which /= STRAIN_TOTAL) then
            do g = 1, rule%n
                eps(:, g) = eps(:, g) - [eps0(1:3, g), 0.5_dp * eps0(4, g)]
                if (which == STRAIN_INELASTIC) then
                    call elastic_strain(law%d4, sig(:, g), elastic, st)
                    if (st%failed()) then
                        st%message = cell_label(res%mesh, c) // ': ' // st%message
                        return
                    end if
                    eps(:, g) = eps(:, g) - [elastic(1:3), 0.5_dp * elastic(4)]
                end if
            end do
        end if
        if (stresses) then
            values(1:4 * rule%n) = reshape(sig(:, 1:rule%n), [4 * rule%n])
        else
            values(1:4 * rule%n) = reshape(eps(:, 1:rule%n), [4 * rule%n])
        end if
    end subroutine plane_cell_values

    ! The elastic strain (xx, yy, zz, xy engineering) of stress sig under the 3D stiffness
    ! d4 on (xx, yy, zz, xy): d4 e = sig, by Gaussian elimination with partial pivoting
    ! (d4 is positive definite: the plane laws check it).
    subroutine elastic_strain(d4, sig, e, st)
        real(dp), intent(in) :: d4(4, 4), sig(4)
        real(dp), intent(out) :: e(4)
        type(status_t), intent(inout) :: st
        real(dp) :: a(4, 5), row(5)
        integer(i4) :: i, j, p
        a(:, 1:4) = d4
        a(:, 5) = sig
        e = 0.0_dp
        do i = 1, 4
            p = i - 1 + maxloc(abs(a(i:4, i)), 1)
            if (.not. abs(a(p, i)) > 0.0_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'its elastic law is singular: no ' // &
                    'elastic strain for EPSP')
                return
            end if
            row = a(p, :)
            a(p, :) = a(i, :)
            a(i, :) = row
            do j = i + 1, 4
                a(j, i:5) = a(j, i:5) - (a(j, i) / a(i, i)) * a(i, i:5)
            end do
        end do
        do i = 4, 1, -1
            e(i) = (a(i, 5) - dot_product(a(i, i + 1:4), e(i + 1:4))) / a(i, i)
        end do
    end subroutine elastic_strain

    !> A plate option (plate_options kind) on the plate cells of `cells` (every plate cell
    !> when absent), at RIGI points (ELGA) or at the nodes (ELNO, evaluated there).
    !>  location : in, FIELD_ELGA or FIELD_ELNO
    !>  quantity, cmps : in, the field's quantity and the kind's components
    subroutine plate_field(res, u, kind, location, quantity, cmps, f, st, cells, inst)
        type(result_concept_t), intent(in) :: res
        real(dp), intent(in) :: u(:)
        integer(i4), intent(in) :: kind, location
        character(len=*), intent(in) :: quantity, cmps
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: cells(:)
        real(dp), intent(in), optional :: inst     !< the instant (thermal strains, elem's)
        type(string_t), allocatable :: names(:)
        type(component_set_t) :: sets(1)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        integer(i4) :: c, j
        logical :: want
        call split_words(cmps, names)
        call field_init_cells(f, location, quantity, names, res%mesh%n_cells, st)
        if (st%failed()) return
        sets(1)%cmp = [(j, j = 1, size(names, kind=i4))]
        allocate (n_points(res%mesh%n_cells), n_sub(res%mesh%n_cells), &
            cell_set(res%mesh%n_cells), source=0_i4)
        do c = 1, res%mesh%n_cells
            want = is_plate(res%model%element(c))
            if (present(cells)) want = want .and. cells(c)
            if (.not. want) cycle
            n_points(c) = res%mesh%cell_ptr(c + 1) - res%mesh%cell_ptr(c)
            n_sub(c) = 1
            if (kind == PLATE_STRESS .or. kind == PLATE_STRAIN) n_sub(c) = 3 * max(1_i4, &
                res%cara%coque_layers(c))
            cell_set(c) = 1
        end do
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, res%mesh%n_cells
            if (n_points(c) == 0) cycle
            call plate_cell_values(res, c, u, kind, location == FIELD_ELNO, &
                f%values(f%offset(c) + 1:f%offset(c + 1)), st, inst)
            if (st%failed()) return
        end do
    end subroutine plate_field

    !> The values of one plate cell, at its RIGI points or at its nodes; with `inst`, the
    !> stresses and forces without the thermal strains of AFFE_VARC there (assembly_varc).
    subroutine plate_cell_values(res, c, u, kind, at_nodes, values, st, inst)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: c, kind
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: at_nodes
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: inst
        logical :: has
        type(plate_cell_t) :: pc
        type(gauss_rule_t) :: rule
        integer(i4) :: np
        call plate_prepare(res%mesh, res%dofs, res%cara, res%materials, c, u, pc, st)
        if (st%failed()) return
        call gauss_family(FORMULATION_PLATE, res%mesh%cell_type(c), &
            trim(merge('NOEU', 'RIGI', at_nodes)), rule, st)
        if (st%failed()) return
        np = rule%n
        if (size(values) /= np * plate_value_count(kind, pc%layers)) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(res%mesh, c) // ': ' // &
                to_text(size(values)) // ' values expected')
            return
        end if
        if (present(inst) .and. (kind == PLATE_STRESS .or. kind == PLATE_FORCES)) then
            allocate (pc%eps_th(3 * pc%layers, np))
            call plate_thermal_strains(res%mesh, res%materials, res%cara, c, inst, &
                rule%xi(:, 1:np), pc%eps_th, has, st)
            if (st%failed()) return
            if (.not. has) deallocate (pc%eps_th)
        end if
        call plate_values(pc, kind, rule%xi(:, 1:np), np, values)
    end subroutine plate_cell_values

    !> N VY (VZ) of a DIS_CHOC spring as the analysis stored it (both points alike).
    subroutine stored_spring_values(res, k, at, np, n_cmp, values)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: k, at, np, n_cmp
        real(dp), intent(out) :: values(:)
        integer(i4) :: p
        do p = 1, np
            values((p - 1) * n_cmp + 1:p * n_cmp) = res%spring_sief(1:n_cmp, k, at)
        end do
    end subroutine stored_spring_values

    !> N VY (VZ) of a linear discrete from its internal forces f = K u turned to its element
    !> frame: SEG2 (x node 1 -> node 2, roll of ORIENTATION; a zero-length segment the
    !> global frame) point 1 = -f(node 1), point 2 = f(node 2); POI1 (frame of ORIENTATION's
    !> nautical angles, else global) the force on its node (Code_Aster ef0042).
    subroutine linear_spring_values(s, c, u, np, n_cmp, values, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, np, n_cmp
        real(dp), intent(in) :: u(:)
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: st
        integer(i4) :: eqs(MAX_ELEMENT_DOFS), n, i, p0
        real(dp) :: ue(MAX_ELEMENT_DOFS), fe(MAX_ELEMENT_DOFS), fn
        real(dp), allocatable :: kfull(:, :)
        real(dp) :: frame(3, 3), x(3, 2), f1(3), f2(3), r2(2, 2), roll
        logical :: closed
        call element_equations(s, c, eqs, n)
        ue = 0.0_dp
        do i = 1, n
            if (eqs(i) > 0) ue(i) = u(eqs(i))
        end do
        allocate (kfull(n, n))
        call cell_response(s, c, ue(1:n), n, .false., .false., kfull, fe(1:n), closed, fn, st)
        if (st%failed()) return
        frame = 0.0_dp
        do i = 1, 3
            frame(i, i) = 1.0_dp
        end do
        p0 = s%mesh%cell_ptr(c)
        if (s%mesh%cell_type(c) == CELL_SEG2) then
            x = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + 1))
            if (norm2(x(:, 2) - x(:, 1)) > 0.0_dp) then
                if (n_cmp == 2) then
                    call segment_rotation_2d(x(1:2, 1), x(1:2, 2), r2, st)
                    frame = 0.0_dp
                    frame(1:2, 1:2) = r2
                    frame(3, 3) = 1.0_dp
                else
                    roll = 0.0_dp
                    if (s%cara%orientation(c) == ORIENT_ANGL_VRIL) &
                        roll = s%cara%orientation_values(1, c)
                    if (s%cara%orientation(c) == ORIENT_ANGL_NAUT) &
                        roll = s%cara%orientation_values(3, c)
                    call segment_rotation(x(:, 1), x(:, 2), roll, frame, st)
                end if
                if (st%failed()) return
            end if
            f1 = 0.0_dp
            f2 = 0.0_dp
            f1(1:n / 2) = fe(1:n / 2)
            f2(1:n / 2) = fe(n / 2 + 1:n)
            values(1:n_cmp) = -matmul(frame(1:n_cmp, :), f1)
            if (np > 1) values(n_cmp + 1:2 * n_cmp) = matmul(frame(1:n_cmp, :), f2)
        else
            if (s%cara%orientation(c) == ORIENT_ANGL_NAUT .and. n_cmp == 3) &
                call nautical_rotation(s%cara%orientation_values(:, c), frame)
            f1 = 0.0_dp
            f1(1:n) = fe(1:n)
            values(1:n_cmp) = matmul(frame(1:n_cmp, :), f1)
        end if
    end subroutine linear_spring_values

end module element_fields
