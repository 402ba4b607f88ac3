!> Code_Aster export files (doc/aster-tests.md): what `run_aster CASE.export` reads, so that
!> `parasol CASE.export` runs a Code_Aster test file for file. One line each:
!>   P NAME VALUE...          a parameter (time_limit: a wall-clock limit in seconds)
!>   A NAME VALUE...          an argument of the old run_aster (recorded)
!>   F TYPE PATH FLAGS UNIT   a file: FLAGS D (data, read), R (result, written), C
!>   R TYPE PATH FLAGS UNIT   a folder (Code_Aster's databases, repe): reported
!> Blank lines and lines starting with # are skipped. A PATH may hold spaces (the words
!> between TYPE and FLAGS); a relative PATH is relative to the export file's folder.
!> Every error is located `CASE.export:LINE: error: ...` and says what would be right. The
!> result files parasol writes are checked before the run (export_result_problem).
module export_file
    use kinds, only: dp
    use strings, only: string_t, to_text, join_words, ends_with
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_DECK_ERROR
    use deck_interpreter, only: read_source_text
    use mesh_text_lexer, only: parse_real
    use system_error, only: path_kind, folder_of, canonical_path, PATH_FOLDER, PATH_MISSING
    implicit none
    private

    !> Result types parasol writes: its listings, and meshes/results on a unit (IMPR_RESU).
    character(len=*), parameter :: WRITTEN_TYPES = ' mess resu rmed mmed med msh '
    !> Any other type word is accepted, as run_aster accepts it (msup, libr, datg, tab, ...):
    !> a file with a unit is bound to it (a command reading or writing that unit uses it),
    !> one without is reported in the .mess.

    !> One F or R line.
    !>  folder : an R line;  type : comm, mmed, ...;  name : the path as written
    !>  path : name joined to the export file's folder when relative
    !>  data, result : flags D, R;  unit : the logical unit;  line : its line number
    type, public :: export_entry_t
        logical :: folder = .false.
        character(len=:), allocatable :: type, name, path
        logical :: data = .false., result = .false.
        integer :: unit = 0
        integer :: line = 0
    end type export_entry_t

    !> A P or A line, as written.
    type, public :: export_param_t
        character(len=1) :: kind = 'P'
        character(len=:), allocatable :: name, value
        integer :: line = 0
    end type export_param_t

    !> A parsed export file.
    !>  path : as given;  dir : its folder ('' or ending with '/');  stem : CASE
    !>  time_limit > 0 when a P time_limit line gives one (its line: time_limit_line)
    type, public :: export_t
        character(len=:), allocatable :: path, dir, stem
        type(export_entry_t), allocatable :: entries(:)
        type(export_param_t), allocatable :: params(:)
        real(dp) :: time_limit = 0.0_dp
        integer :: time_limit_line = 0
    contains
        procedure :: command_files => export_command_files
        procedure :: describe => export_describe
        procedure :: result_problem => export_result_problem
    end type export_t

    public :: read_export, parse_export, is_export_path, module_name

contains

    !> True for a path ending with `.export`.
    pure logical function is_export_path(path)
        character(len=*), intent(in) :: path
        is_export_path = .false.
        if (len(path) > 7) is_export_path = path(len(path) - 6:) == '.export'
    end function is_export_path

    !> Reads and parses the export file `path` (parse_export), then checks that every data
    !> file it names exists.
    !>  exp : out;  st : out, STATUS_IO_ERROR (unreadable, missing file) or
    !>        STATUS_DECK_ERROR (bad line), located CASE.export:LINE
    subroutine read_export(path, exp, st)
        character(len=*), intent(in) :: path
        type(export_t), intent(out) :: exp
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text, problem
        integer :: k
        logical :: exists
        call read_source_text(path, 'the export file', text, st)
        if (st%failed()) return
        call parse_export(path, text, exp, st)
        if (st%failed()) return
        do k = 1, size(exp%entries)
            associate (e => exp%entries(k))
                if (e%data) then
                    inquire (file=e%path, exist=exists)
                    if (.not. exists) then
                        call set_error(st, STATUS_IO_ERROR, 'file not found: ' // e%path // &
                            ' (F ' // e%type // ' ' // e%name // ': a data file must ' // &
                            'exist; a relative name is relative to the export file''s ' // &
                            'folder)', file=path, line=e%line)
                        return
                    end if
                end if
                problem = exp%result_problem(k)
                if (len(problem) > 0) then
                    call set_error(st, STATUS_IO_ERROR, problem, file=path, line=e%line)
                    return
                end if
            end associate
        end do
    end subroutine read_export

    !> What is wrong with entry k as a result file parasol writes ('' when nothing, or when
    !> parasol does not write it), checked before the run starts so that no listing is
    !> lost at its end: its folder must exist, it must not name a folder, and no earlier
    !> result line may name the same file (the .mess and the .resu on one file would
    !> overwrite each other).
    function export_result_problem(self, k) result(problem)
        class(export_t), intent(in) :: self
        integer, intent(in) :: k
        character(len=:), allocatable :: problem, line_text, folder, here
        integer :: j
        problem = ''
        if (.not. written_result(self%entries(k))) return
        associate (e => self%entries(k))
            line_text = 'F ' // e%type // ' ' // e%name // ' R ' // to_text(e%unit) // ': '
            if (path_kind(e%path) == PATH_FOLDER) then
                problem = line_text // e%name // ' is a folder; a result line names the ' // &
                    'file parasol writes (e.g. F ' // e%type // ' ' // self%stem // '.' // &
                    e%type // ' R ' // to_text(e%unit) // ')'
                return
            end if
            folder = folder_of(e%path)
            if (path_kind(folder) /= PATH_FOLDER) then
                problem = line_text // 'the folder ' // folder // ' does not exist (the ' // &
                    'folder of a result file must exist before the run: create it, or name ' &
                    // 'a file in an existing folder; a relative name is relative to the ' // &
                    'export file''s folder)'
                if (path_kind(folder) /= PATH_MISSING) problem = line_text // folder // &
                    ' is not a folder (the result file ' // e%name // ' cannot be made in it)'
                return
            end if
            here = canonical_path(e%path)
            do j = 1, k - 1
                if (.not. written_result(self%entries(j))) cycle
                if (canonical_path(self%entries(j)%path) /= here) cycle
                problem = line_text // 'the same file as line ' // &
                    to_text(self%entries(j)%line) // ' (F ' // self%entries(j)%type // ' ' // &
                    self%entries(j)%name // ' R ' // to_text(self%entries(j)%unit) // &
                    '): each result needs a file of its own'
                return
            end do
        end associate
    end function export_result_problem

    ! A result file parasol writes: a listing (mess, resu) or a mesh/result on a unit.
    pure logical function written_result(e)
        type(export_entry_t), intent(in) :: e
        written_result = .not. e%folder .and. e%result .and. &
            index(WRITTEN_TYPES, ' ' // e%type // ' ') > 0
    end function written_result

    !> Parses the text of an export file (no file system access but the name).
    !>  path : in, the export file (messages, folder of relative names)
    !>  exp : out;  st : out, STATUS_DECK_ERROR located at the bad line
    subroutine parse_export(path, text, exp, st)
        character(len=*), intent(in) :: path, text
        type(export_t), intent(out) :: exp
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: words(:)
        integer :: start, i, line, slash, dot
        slash = index(path, '/', back=.true.)
        exp%path = path
        exp%dir = path(1:slash)
        exp%stem = path(slash + 1:)
        dot = index(exp%stem, '.', back=.true.)
        if (dot > 1) exp%stem = exp%stem(1:dot - 1)
        allocate (exp%entries(0), exp%params(0))
        if (index(text, achar(0)) > 0) then
            call set_error(st, STATUS_DECK_ERROR, 'NUL byte: this is not an export file ' // &
                '(a text file of P, A, F and R lines)', file=path, line=1)
            return
        end if
        start = 1; line = 0
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= achar(10)) cycle
            end if
            line = line + 1
            call split_words(text(start:i - 1), words)
            start = i + 1
            if (size(words) == 0) cycle
            if (words(1)%s(1:1) == '#') cycle
            call parse_line(exp, words, line, st)
            if (st%failed()) return
        end do
        if (size(exp%command_files()) == 0) then
            ! located at the end of the file, where the missing line would be
            call set_error(st, STATUS_DECK_ERROR, 'no command file: an export file names ' // &
                'its decks with lines "F comm NAME.comm D 1"', file=path, &
                line=max(1, line - merge(1, 0, len(text) > 0 .and. ends_with(text, achar(10)))))
        end if
    end subroutine parse_export

    !> One non-blank, non-comment line.
    subroutine parse_line(exp, words, line, st)
        type(export_t), intent(inout) :: exp
        type(string_t), intent(in) :: words(:)
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        select case (words(1)%s)
        case ('P', 'A')
            if (size(words) < 2) then
                call fail(words(1)%s // ' line without a name (P NAME VALUE..., e.g. ' // &
                          'P time_limit 60)'); return
            end if
            call add_param(exp, words, line)
            if (words(1)%s == 'P' .and. words(2)%s == 'time_limit') &
                call read_time_limit(exp, words, line, st)
        case ('F', 'R')
            call add_entry(exp, words, line, st)
        case default
            call fail('unknown line kind "' // words(1)%s // '" (an export line starts ' // &
                      'with P, A, F or R)')
        end select
    contains
        subroutine fail(message)
            character(len=*), intent(in) :: message
            call line_error(exp, line, message, st)
        end subroutine fail
    end subroutine parse_line

    !> An error located at `line` of the export file.
    subroutine line_error(exp, line, message, st)
        type(export_t), intent(in) :: exp
        integer, intent(in) :: line
        character(len=*), intent(in) :: message
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_DECK_ERROR, message, file=exp%path, line=line)
    end subroutine line_error

    subroutine add_param(exp, words, line)
        type(export_t), intent(inout) :: exp
        type(string_t), intent(in) :: words(:)
        integer, intent(in) :: line
        type(export_param_t), allocatable :: bigger(:)
        integer :: k, n
        n = size(exp%params)
        allocate (bigger(n + 1))
        do k = 1, n
            bigger(k) = exp%params(k)
        end do
        bigger(n + 1)%kind = words(1)%s
        bigger(n + 1)%name = words(2)%s
        bigger(n + 1)%value = join_words(words(3:), ' ')
        bigger(n + 1)%line = line
        call move_alloc(bigger, exp%params)
    end subroutine add_param

    !> P time_limit SECONDS: one positive number (run_aster's limit for the whole run).
    subroutine read_time_limit(exp, words, line, st)
        type(export_t), intent(inout) :: exp
        type(string_t), intent(in) :: words(:)
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        real(dp) :: x
        logical :: ok
        ok = .false.
        ! parse_real: a Fortran read of 1e309 traps in the checked build (fuzz seed 2024
        ! case 260, "P time_limit -1e309")
        if (size(words) == 3) call parse_real(words(3)%s, x, ok)
        if (ok) ok = x > 0.0_dp .and. x < 1.0e9_dp
        if (.not. ok) then
            call line_error(exp, line, 'P time_limit expects one positive number of ' // &
                'seconds (e.g. P time_limit 60), got "' // join_words(words(3:), ' ') // '"', st)
            return
        end if
        exp%time_limit = x
        exp%time_limit_line = line
    end subroutine read_time_limit

    !> F|R TYPE PATH... FLAGS UNIT
    subroutine add_entry(exp, words, line, st)
        type(export_t), intent(inout) :: exp
        type(string_t), intent(in) :: words(:)
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        type(export_entry_t) :: e
        type(export_entry_t), allocatable :: bigger(:)
        character(len=:), allocatable :: flags
        integer :: k, n, ios
        if (size(words) < 5) then
            call fail(words(1)%s // ' line needs 4 fields: ' // words(1)%s // &
                      ' TYPE NAME FLAGS UNIT (e.g. F comm case.comm D 1)'); return
        end if
        e%folder = words(1)%s == 'R'
        e%type = words(2)%s
        e%name = join_words(words(3:size(words) - 2), ' ')
        flags = words(size(words) - 1)%s
        e%line = line
        if (verify(flags, 'DRC') /= 0) then
            call fail('bad flags "' // flags // '" (D = data read, R = result written, ' // &
                      'C = compressed; e.g. D, R or DR)'); return
        end if
        e%data = index(flags, 'D') > 0
        e%result = index(flags, 'R') > 0
        ios = 1
        if (verify(words(size(words))%s, '0123456789') == 0 .and. &
            len(words(size(words))%s) <= 9) read (words(size(words))%s, *, iostat=ios) e%unit
        if (ios /= 0) then
            call fail('bad logical unit "' // words(size(words))%s // '" (a number >= 0, ' // &
                      'e.g. 20 for a mesh, 1 for a command file)'); return
        end if
        if (.not. (e%data .or. e%result)) then
            call fail('flags "' // flags // '" give neither D (data) nor R (result)'); return
        end if
        if (e%type == 'comm' .and. .not. e%data) then
            call fail('a command file is data: F comm NAME D 1'); return
        end if
        if (index(' mmed med mail msh ', ' ' // e%type // ' ') > 0 .and. e%data .and. &
            e%unit == 0) then
            call fail('a mesh file needs its logical unit (LIRE_MAILLAGE reads UNITE=20 ' // &
                      'by default: F ' // e%type // ' ' // e%name // ' D 20)'); return
        end if
        e%path = e%name
        if (e%name(1:1) /= '/') e%path = exp%dir // e%name
        n = size(exp%entries)
        allocate (bigger(n + 1))
        do k = 1, n
            bigger(k) = exp%entries(k)
        end do
        bigger(n + 1) = e
        call move_alloc(bigger, exp%entries)
    contains
        subroutine fail(message)
            character(len=*), intent(in) :: message
            call line_error(exp, line, message, st)
        end subroutine fail
    end subroutine add_entry

    !> Indices of the F comm lines, in order: the command files of the session.
    function export_command_files(self) result(idx)
        class(export_t), intent(in) :: self
        integer, allocatable :: idx(:)
        integer :: k
        allocate (idx(0))
        do k = 1, size(self%entries)
            if (self%entries(k)%type == 'comm' .and. .not. self%entries(k)%folder) &
                idx = [idx, k]
        end do
    end function export_command_files

    !> One line for the .mess saying what parasol does with entry k.
    function export_describe(self, k) result(text)
        class(export_t), intent(in) :: self
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        character(len=:), allocatable :: what
        associate (e => self%entries(k))
            text = merge('R ', 'F ', e%folder) // e%type // ' ' // e%name // ' ' // &
                trim(merge('D', ' ', e%data)) // trim(merge('R', ' ', e%result)) // ' ' // &
                to_text(e%unit) // ' (line ' // to_text(e%line) // '): '
            if (e%folder) then
                what = 'a folder; not used by parasol'
            else if (e%type == 'comm') then
                what = 'command file, run in order'
            else if (e%type == 'nom') then
                what = 'Python module ' // module_name(e%name) // ' for from ... import'
            else if (index(' mmed med mail msh ', ' ' // e%type // ' ') > 0 .and. e%data) then
                what = 'bound to logical unit ' // to_text(e%unit)
            else if (e%result .and. (e%type == 'mess' .or. e%type == 'resu')) then
                what = 'the .' // e%type // ' listing is written there'
            else if (e%result .and. index(WRITTEN_TYPES, ' ' // e%type // ' ') > 0) then
                what = 'bound to logical unit ' // to_text(e%unit) // ' (IMPR_RESU UNITE=' // &
                    to_text(e%unit) // ' writes it)'
            else if (e%unit > 0 .and. e%type /= 'mess' .and. e%type /= 'resu') then
                what = 'bound to logical unit ' // to_text(e%unit) // ' (a command that ' // &
                    'reads or writes unit ' // to_text(e%unit) // ' uses it)'
            else if (e%result) then
                what = 'not written: parasol writes no ' // e%type // ' file'
            else
                what = 'not read: parasol has no use for a ' // e%type // ' file'
            end if
            text = text // what
        end associate
    end function export_describe

    !> The module name of a Python file: its name without folder and .py.
    function module_name(path) result(name)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: name
        integer :: slash
        slash = index(path, '/', back=.true.)
        name = path(slash + 1:)
        if (len(name) > 3) then
            if (name(len(name) - 2:) == '.py') name = name(1:len(name) - 3)
        end if
    end function module_name

    !> Words of a line separated by blanks, tabs or a CR.
    subroutine split_words(text, words)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: words(:)
        type(string_t), allocatable :: bigger(:)
        integer :: i, j, k, n
        character(len=*), parameter :: blanks = ' ' // achar(9) // achar(13)
        allocate (words(0))
        i = 1
        do while (i <= len(text))
            if (index(blanks, text(i:i)) > 0) then
                i = i + 1
                cycle
            end if
            j = i
            do while (j < len(text))
                if (index(blanks, text(j + 1:j + 1)) > 0) exit
                j = j + 1
            end do
            n = size(words)
            allocate (bigger(n + 1))
            do k = 1, n
                bigger(k)%s = words(k)%s
            end do
            bigger(n + 1)%s = text(i:j)
            call move_alloc(bigger, words)
            i = j + 1
        end do
    end subroutine split_words


end module export_file
