!> Discretes whose stiffness is not symmetric: AFFE_CARA_ELEM DISCRET / DISCRET_2D with
!> SYME='NON' (Code_Aster U4.42.01 §5: the whole matrix given by column, K(i,j) /= K(j,i)).
!> Each such element matrix splits as K_e = S_e + N_e, S_e = (K_e + K_e^T)/2 the symmetric
!> part, which the assembled matrix holds (assembly_system cell_response), and
!> N_e = (K_e - K_e^T)/2 the skew part, which this module gathers on the equations it acts
!> on so that the analysis solves with S + N exactly (unsymmetric_correction). Internal
!> forces, hence residuals and REAC_NODA, use K_e whole.
module assembly_unsymmetric
    use kinds, only: dp, i4
    use status, only: status_t, set_error
    use mesh_types, only: cell_label
    use model_cara_elem, only: discrete_is_unsymmetric
    use model_types, only: ELEM_NONE
    use assembly_system, only: structure_t, assembly_map_t, element_equations, &
        discrete_matrix, MAX_ELEMENT_DOFS
    implicit none
    private

    public :: first_unsymmetric_cell, skew_stiffness

contains

    !> The first modelled cell whose discrete stiffness is not symmetric, 0 if none.
    integer(i4) function first_unsymmetric_cell(s) result(c)
        type(structure_t), intent(in) :: s
        integer(i4) :: k
        c = 0
        do k = 1, s%mesh%n_cells
            if (s%model%element(k) == ELEM_NONE) cycle
            if (discrete_is_unsymmetric(s%cara, k)) then
                c = k
                return
            end if
        end do
    end function first_unsymmetric_cell

    !> N = sum of the skew parts N_e of the unsymmetric discretes of map%cells, on the
    !> original equations they act on that are not imposed (an imposed equation carries no
    !> unknown: its rows and columns of N drop out exactly).
    !>  eqs  : out, (m) those equations, in the order first met (cells in map order)
    !>  skew : out, (m, m) N on them: N(i, j) multiplies u(eqs(j)) in the force on eqs(i);
    !>         not allocated when m > limit (N is dense: the caller refuses so many)
    !>  st   : out, a discrete whose frame cannot be built (naming the cell)
    !>  limit : in, the most equations N is built on
    subroutine skew_stiffness(s, map, limit, eqs, skew, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: limit
        integer(i4), allocatable, intent(out) :: eqs(:)
        real(dp), allocatable, intent(out) :: skew(:, :)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: local(:)
        integer(i4) :: k, c, n, i, j, m, p0, nn, e(MAX_ELEMENT_DOFS), le(MAX_ELEMENT_DOFS)
        real(dp) :: x(3, 2)
        real(dp), allocatable :: ke(:, :)
        allocate (local(s%dofs%n_equations), source=0_i4)
        ! first pass: the equations, numbered as met
        m = 0
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (.not. discrete_is_unsymmetric(s%cara, c)) cycle
            call element_equations(s, c, e, n)
            do i = 1, n
                if (e(i) <= 0) cycle
                if (map%imposed(e(i))) cycle
                if (local(e(i)) > 0) cycle
                m = m + 1
                local(e(i)) = m
            end do
        end do
        allocate (eqs(m))
        do i = 1, s%dofs%n_equations
            if (local(i) > 0) eqs(local(i)) = i
        end do
        if (m > limit) return
        allocate (skew(m, m), source=0.0_dp)
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (.not. discrete_is_unsymmetric(s%cara, c)) cycle
            call element_equations(s, c, e, n)
            p0 = s%mesh%cell_ptr(c)
            nn = s%mesh%cell_ptr(c + 1) - p0
            x = 0.0_dp
            x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
            if (allocated(ke)) deallocate (ke)
            allocate (ke(n, n))
            call discrete_matrix(s, c, x, n, ke, st)
            if (st%failed()) then
                call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
                return
            end if
            le(1:n) = 0
            do i = 1, n
                if (e(i) > 0) le(i) = local(e(i))
            end do
            do j = 1, n
                if (le(j) == 0) cycle
                do i = 1, n
                    if (le(i) == 0) cycle
                    skew(le(i), le(j)) = skew(le(i), le(j)) + 0.5_dp * (ke(i, j) - ke(j, i))
                end do
            end do
        end do
    end subroutine skew_stiffness

end module assembly_unsymmetric
