!> parasol-bench skyline: factor and solve an SPD matrix with the pattern of a plate mesh with
!> the skyline LDL^T solver and with LAPACK DPBTRF/DPBTRS on the same ordering and band
!> (doc/performance.md, "Skyline solver").
!>
!> Matrix: NX x NY quadrilateral cells (4 nodes), D DOFs per node; each element adds a
!> symmetric matrix with entries in [-1, 1) from a 64-bit LCG seeded by the element number
!> (deterministic); the diagonal is then set to the row sum of |a_ij| + 1 (strictly
!> diagonally dominant, hence SPD). Nodes are renumbered (RCMK, METIS or SANS) and the D
!> equations of a node are consecutive. Timings: wall clock (system_clock) of factor + solve.
module bench_skyline
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp, i4, i8
    use status, only: status_t, format_status, set_error, STATUS_INTERNAL
    use strings, only: string_t, to_text, real_short
    use renumbering, only: graph_from_elements, renumber_graph, graph_profile
    use skyline_matrix, only: skyline_t, skyline_start_profile, skyline_add_connectivity, &
        skyline_finish_profile, skyline_add_element, skyline_zero, skyline_matvec, &
        skyline_profile_size, skyline_bandwidth, skyline_mean_height, skyline_column_top
    use skyline_solver, only: skyline_factor, skyline_solve, factor_options_t, &
        factor_report_t, FACTOR_AUTO, FACTOR_REFERENCE, FACTOR_BLOCKED
    use lapack_interface, only: dpbtrf, dpbtrs
    implicit none
    private
    public :: run_bench_skyline

    !> DPBTRF is skipped beyond 1e9 band entries (8 GB; also below LAPACK's 32-bit index
    !> limit 2**31) or N KD^2 = 2e12 flops (minutes): wide METIS bands would not finish.
    integer(i8), parameter :: MAX_BAND_ENTRIES = 1000000000_i8
    real(dp), parameter :: MAX_BAND_FLOPS = 2.0e12_dp

    !> The benchmark's parameters (command line).
    type :: plate_case_t
        integer(i4) :: nx = 16, ny = 64, dofs = 6, repeat = 1
        character(len=8) :: renum = 'RCMK'
        integer(i4) :: kernel = FACTOR_AUTO
        logical :: lapack = .true.
    end type plate_case_t

contains

    !> Runs the benchmark. args: the arguments after "skyline".
    !>  exit_status : out, 0 on success, 1 on bad usage or failure
    subroutine run_bench_skyline(args, exit_status)
        type(string_t), intent(in) :: args(:)
        integer, intent(out) :: exit_status
        type(plate_case_t) :: pc
        type(status_t) :: st
        logical :: ok
        exit_status = 1
        call parse_options(args, pc, ok)
        if (.not. ok) return
        call run_case(pc, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-bench skyline: ' // format_status(st)
            return
        end if
        exit_status = 0
    end subroutine run_bench_skyline

    subroutine parse_options(args, pc, ok)
        type(string_t), intent(in) :: args(:)
        type(plate_case_t), intent(out) :: pc
        logical, intent(out) :: ok
        integer :: k, ios
        ok = .false.
        k = 1
        do while (k <= size(args))
            if (args(k)%s == '--no-lapack') then
                pc%lapack = .false.
                k = k + 1
                cycle
            end if
            if (k == size(args)) then
                write (error_unit, '(a)') 'parasol-bench skyline: ' // args(k)%s // ' needs a value'
                return
            end if
            ios = 0
            select case (args(k)%s)
            case ('--nx')
                read (args(k + 1)%s, *, iostat=ios) pc%nx
            case ('--ny')
                read (args(k + 1)%s, *, iostat=ios) pc%ny
            case ('--dofs')
                read (args(k + 1)%s, *, iostat=ios) pc%dofs
            case ('--repeat')
                read (args(k + 1)%s, *, iostat=ios) pc%repeat
            case ('--renum')
                pc%renum = args(k + 1)%s
            case ('--kernel')
                select case (args(k + 1)%s)
                case ('auto')
                    pc%kernel = FACTOR_AUTO
                case ('reference')
                    pc%kernel = FACTOR_REFERENCE
                case ('blocked')
                    pc%kernel = FACTOR_BLOCKED
                case default
                    ios = 1
                end select
            case default
                ios = 1
            end select
            if (ios /= 0 .or. min(pc%nx, pc%ny, pc%dofs, pc%repeat) < 1) then
                write (error_unit, '(a)') 'parasol-bench skyline: bad option ' // args(k)%s // &
                    ' ' // args(k + 1)%s
                call print_skyline_usage(error_unit)
                return
            end if
            k = k + 2
        end do
        ok = .true.
    end subroutine parse_options

    subroutine print_skyline_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: parasol-bench skyline [--nx NX] [--ny NY] [--dofs D] ' // &
            '[--renum RCMK|METIS|SANS] [--kernel auto|reference|blocked] [--repeat R] ' // &
            '[--no-lapack]'
    end subroutine print_skyline_usage

    !> Builds, renumbers, assembles, factors and solves one case; prints the RESULT line.
    subroutine run_case(pc, st)
        type(plate_case_t), intent(in) :: pc
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: elem_ptr(:), elem_nodes(:), xadj(:), adj(:), n2o(:), o2n(:)
        integer(i4), allocatable :: eqs(:, :)
        integer(i4) :: n_nodes, n, band0, band1, kd, k, rep
        logical :: use_band
        integer(i8) :: prof0, prof1
        type(skyline_t) :: sky
        real(dp), allocatable :: b(:), x(:), xb(:)
        real(dp) :: t_sky, t_band, r_sky, r_band, t
        call plate_mesh(pc%nx, pc%ny, elem_ptr, elem_nodes)
        n_nodes = (pc%nx + 1) * (pc%ny + 1)
        call graph_from_elements(n_nodes, elem_ptr, elem_nodes, xadj, adj, st)
        if (st%failed()) return
        call renumber_graph(pc%renum, n_nodes, xadj, adj, n2o, o2n, st)
        if (st%failed()) return
        call graph_profile(n_nodes, xadj, adj, [(k, k = 1, n_nodes)], prof0, band0, pc%dofs)
        call graph_profile(n_nodes, xadj, adj, o2n, prof1, band1, pc%dofs)
        n = n_nodes * pc%dofs
        write (output_unit, '(a)') 'plate ' // to_text(pc%nx) // ' x ' // to_text(pc%ny) // &
            ' cells, ' // to_text(pc%dofs) // ' DOF/node, ' // to_text(n) // ' equations'
        write (output_unit, '(a)') 'renumbering ' // trim(pc%renum) // ': profile ' // &
            to_text(prof0) // ' -> ' // to_text(prof1) // ', bandwidth ' // to_text(band0) &
            // ' -> ' // to_text(band1)
        call element_equations(pc, elem_nodes, o2n, eqs)
        call build_plate_matrix(n, eqs, sky, st)
        if (st%failed()) return
        kd = skyline_bandwidth(sky)
        write (output_unit, '(a)') 'skyline: profile ' // to_text(skyline_profile_size(sky)) &
            // ', bandwidth ' // to_text(kd) // ', mean column height ' // &
            real_short(skyline_mean_height(sky))
        allocate (b(n), x(n))
        call right_hand_side(b)
        use_band = pc%lapack
        if (pc%lapack .and. (int(kd + 1, i8) * n > MAX_BAND_ENTRIES .or. &
                             real(n, dp) * real(kd, dp)**2 > MAX_BAND_FLOPS)) then
            write (output_unit, '(a)') 'dpbtrf: skipped, band storage (KD+1) x N = ' // &
                to_text(int(kd + 1, i8) * n) // ' entries or N KD^2 = ' // &
                real_short(real(n, dp) * real(kd, dp)**2) // ' flops is out of reach'
            use_band = .false.
        end if
        ! Shared machines are noisy: the best of --repeat runs is reported for each solver.
        t_band = huge(1.0_dp)
        t_sky = huge(1.0_dp)
        do rep = 1, pc%repeat
            if (rep > 1) call build_plate_matrix(n, eqs, sky, st)
            if (use_band) then
                call time_dpbtrf(sky, kd, b, xb, t, st)
                if (st%failed()) return
                t_band = min(t_band, t)
            end if
            x = b
            call time_skyline(sky, pc%kernel, x, t, st)
            if (st%failed()) return
            t_sky = min(t_sky, t)
        end do
        if (.not. use_band) t_band = 0.0_dp
        r_band = 0.0_dp
        call build_plate_matrix(n, eqs, sky, st)
        r_sky = relative_residual(sky, x, b)
        if (allocated(xb)) r_band = relative_residual(sky, xb, b)
        call print_result(n, skyline_profile_size(sky), kd, t_sky, t_band, r_sky, r_band)
    end subroutine run_case

    !> Cells of an nx x ny grid, nodes (i, j) -> i + (j-1)(nx+1), counter-clockwise.
    subroutine plate_mesh(nx, ny, elem_ptr, elem_nodes)
        integer(i4), intent(in) :: nx, ny
        integer(i4), allocatable, intent(out) :: elem_ptr(:), elem_nodes(:)
        integer(i4) :: i, j, e, n1
        allocate (elem_ptr(nx * ny + 1), elem_nodes(4 * nx * ny))
        e = 0
        do j = 1, ny
            do i = 1, nx
                n1 = i + (j - 1) * (nx + 1)
                elem_nodes(4 * e + 1:4 * e + 4) = [n1, n1 + 1, n1 + nx + 2, n1 + nx + 1]
                e = e + 1
                elem_ptr(e) = 4 * e - 3
            end do
        end do
        elem_ptr(e + 1) = 4 * e + 1
    end subroutine plate_mesh

    !> Equations of each element (4 D of them), D consecutive equations per renumbered node.
    subroutine element_equations(pc, elem_nodes, o2n, eqs)
        type(plate_case_t), intent(in) :: pc
        integer(i4), intent(in) :: elem_nodes(:), o2n(:)
        integer(i4), allocatable, intent(out) :: eqs(:, :)
        integer(i4) :: e, k, d
        allocate (eqs(4 * pc%dofs, size(elem_nodes) / 4))
        do e = 1, size(eqs, 2)
            do k = 1, 4
                do d = 1, pc%dofs
                    eqs((k - 1) * pc%dofs + d, e) = (o2n(elem_nodes(4 * (e - 1) + k)) - 1) * &
                                                    pc%dofs + d
                end do
            end do
        end do
    end subroutine element_equations

    !> Profile from the element equations (first call) and assembly of the deterministic
    !> random element matrices, then the diagonal set for strict dominance.
    subroutine build_plate_matrix(n, eqs, sky, st)
        integer(i4), intent(in) :: n, eqs(:, :)
        type(skyline_t), intent(inout) :: sky
        type(status_t), intent(out) :: st
        real(dp), allocatable :: ke(:, :), rowsum(:)
        integer(i4) :: e, a, c, m, j, i, top
        integer(i8) :: seed
        if (.not. sky%profile_ready) then
            call skyline_start_profile(sky, n, st)
            do e = 1, size(eqs, 2)
                call skyline_add_connectivity(sky, eqs(:, e), st)
                if (st%failed()) return
            end do
            call skyline_finish_profile(sky, st)
            if (st%failed()) return
        end if
        call skyline_zero(sky)
        m = size(eqs, 1)
        allocate (ke(m, m), rowsum(n))
        do e = 1, size(eqs, 2)
            seed = int(e, i8) * 7919_i8
            do c = 1, m
                do a = 1, c
                    ke(a, c) = lcg_uniform(seed)
                    ke(c, a) = ke(a, c)
                end do
            end do
            call skyline_add_element(sky, eqs(:, e), ke, st)
            if (st%failed()) return
        end do
        rowsum = 0.0_dp
        do j = 1, n
            top = skyline_column_top(sky, j)
            do i = top, j - 1
                rowsum(i) = rowsum(i) + abs(sky%values(sky%diag(j) - (j - i)))
                rowsum(j) = rowsum(j) + abs(sky%values(sky%diag(j) - (j - i)))
            end do
        end do
        sky%values(sky%diag(1:n)) = rowsum + 1.0_dp
    end subroutine build_plate_matrix

    !> Uniform in [-1, 1) from a 64-bit LCG (Knuth's MMIX constants).
    real(dp) function lcg_uniform(seed)
        integer(i8), intent(inout) :: seed
        seed = seed * 6364136223846793005_i8 + 1442695040888963407_i8
        lcg_uniform = real(ishft(seed, -11), dp) / 2.0_dp**53 * 2.0_dp - 1.0_dp
    end function lcg_uniform

    subroutine right_hand_side(b)
        real(dp), intent(out) :: b(:)
        integer(i4) :: i
        do i = 1, size(b)
            b(i) = 1.0_dp + 0.1_dp * real(mod(i, 7), dp)
        end do
    end subroutine right_hand_side

    !> Factor + solve with the skyline solver; x: b in, solution out.
    subroutine time_skyline(sky, kernel, x, seconds, st)
        type(skyline_t), intent(inout) :: sky
        integer(i4), intent(in) :: kernel
        real(dp), intent(inout) :: x(:)
        real(dp), intent(out) :: seconds
        type(status_t), intent(out) :: st
        type(factor_report_t) :: rep
        type(factor_options_t) :: opt
        integer(i8) :: c0, c1, rate
        opt%method = kernel
        opt%positive_definite = .true.
        call system_clock(c0, rate)
        call skyline_factor(sky, rep, st, opt)
        if (st%failed()) return
        call skyline_solve(sky, x, st)
        call system_clock(c1)
        seconds = real(c1 - c0, dp) / real(rate, dp)
        write (output_unit, '(a)') 'skyline: pivots ' // real_short(rep%min_abs_pivot) // &
            ' .. ' // real_short(rep%max_abs_pivot) // ', max digits lost ' // &
            real_short(rep%max_digits_lost) // ' at equation ' // to_text(rep%max_digits_equation)
    end subroutine time_skyline

    !> Factor + solve with LAPACK DPBTRF/DPBTRS on the band kd of the same ordering.
    subroutine time_dpbtrf(sky, kd, b, xb, seconds, st)
        type(skyline_t), intent(in) :: sky
        integer(i4), intent(in) :: kd
        real(dp), intent(in) :: b(:)
        real(dp), allocatable, intent(out) :: xb(:)
        real(dp), intent(out) :: seconds
        type(status_t), intent(out) :: st
        real(dp), allocatable :: ab(:, :)
        integer(i4) :: j, top, n
        integer :: info
        integer(i8) :: c0, c1, rate
        n = sky%n
        allocate (ab(kd + 1, n))
        do j = 1, n
            top = skyline_column_top(sky, j)
            ab(1:kd - (j - top), j) = 0.0_dp
            ab(kd + 1 - (j - top):kd + 1, j) = sky%values(sky%diag(j - 1) + 1:sky%diag(j))
        end do
        xb = b
        call system_clock(c0, rate)
        call dpbtrf('U', n, kd, ab, kd + 1, info)
        if (info == 0) call dpbtrs('U', n, kd, 1, ab, kd + 1, xb, n, info)
        call system_clock(c1)
        seconds = real(c1 - c0, dp) / real(rate, dp)
        if (info /= 0) then
            call set_error(st, STATUS_INTERNAL, 'DPBTRF/DPBTRS failed, info = ' // &
                           to_text(int(info, i4)))
        end if
    end subroutine time_dpbtrf

    !> ||A x - b|| / ||b|| with the unfactored matrix.
    real(dp) function relative_residual(sky, x, b)
        type(skyline_t), intent(in) :: sky
        real(dp), intent(in) :: x(:), b(:)
        real(dp), allocatable :: r(:)
        allocate (r(size(b)))
        call skyline_matvec(sky, x, r)
        relative_residual = norm2(r - b) / norm2(b)
    end function relative_residual

    subroutine print_result(n, profile, band, t_sky, t_band, r_sky, r_band)
        integer(i4), intent(in) :: n, band
        integer(i8), intent(in) :: profile
        real(dp), intent(in) :: t_sky, t_band, r_sky, r_band
        character(len=:), allocatable :: ratio
        ratio = 'n/a'
        if (t_band > 0.0_dp) ratio = fixed(t_sky / t_band, 3)
        write (output_unit, '(a)') 'RESULT n=' // to_text(n) // ' profile=' // &
            to_text(profile) // ' band=' // to_text(band) // ' t_skyline=' // &
            fixed(t_sky, 4) // ' t_dpbtrf=' // fixed(t_band, 4) // ' ratio=' // ratio // &
            ' resid_skyline=' // real_short(r_sky) // ' resid_dpbtrf=' // real_short(r_band)
    end subroutine print_result

    !> A non-negative real with `digits` decimals.
    function fixed(x, digits) result(text)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: text
        character(len=32) :: buf
        character(len=16) :: fmt
        write (fmt, '(a, i0, a)') '(f0.', digits, ')'
        write (buf, fmt) x
        text = trim(adjustl(buf))
        if (text(1:1) == '.') text = '0' // text
    end function fixed

end module bench_skyline
